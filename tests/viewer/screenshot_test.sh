#!/usr/bin/env bash
# The viewer in a virtual X server (Xvfb, Mesa's software GLES 3): one screenshot without the
# panel (the glass must show), one at the low quality tier (still the glass, from half the
# resolution), one with the panel (the panel must draw).
#   screenshot_test.sh XVFB_RUN VIEWER CHECKER OUTDIR
set -euo pipefail
xvfb_run=$1 viewer=$2 checker=$3 out=$4
mkdir -p "$out"
rm -f "$out"/viewer-*.png

run() {
  # 24-bit screen: GL needs a true-colour visual.
  "$xvfb_run" -a -s "-screen 0 1024x768x24" "$viewer" --preset lager --size 320x240 --frames 30 "$@"
}

run --hide-panel --screenshot "$out/viewer-glass.png"
"$checker" "$out/viewer-glass.png" 320 240 glass
run --hide-panel --quality 0 --screenshot "$out/viewer-low.png"
"$checker" "$out/viewer-low.png" 320 240 glass
run --screenshot "$out/viewer-panel.png"
"$checker" "$out/viewer-panel.png" 320 240 panel "$out/viewer-glass.png"
echo "viewer screenshots: $out/viewer-glass.png $out/viewer-low.png $out/viewer-panel.png"
