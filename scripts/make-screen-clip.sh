#!/usr/bin/env bash
# Makes the shipped screen clip presets/videos/draught-loop.mp4 (about 60 KB) from ffmpeg's
# own sources, nothing downloaded: 4 s at 25 fps, 480 x 270, slow bands of warm colour that
# repeat exactly every 4 s (so the loop has no seam) and the word "draught" bobbing once
# per loop. H.264 (yuv420p, CRF 26) with its index first, so the web page could stream it.
#
#   scripts/make-screen-clip.sh [OUT]
set -euo pipefail
cd "$(dirname "$0")/.."
out="${1:-presets/videos/draught-loop.mp4}"
font=/usr/share/fonts/truetype/dejavu/DejaVuSans-Bold.ttf
[ -f "$font" ] || { echo "make-screen-clip: $font is missing (apt-get install fonts-dejavu-core)" >&2; exit 1; }
# Every term is periodic in T with period 4 s: the last frame leads into the first.
bands="geq=r='175+75*sin(2*PI*(1.5*X/W-T/4))':g='115+55*sin(2*PI*(Y/H+0.5*X/W+T/4))':b='95+80*sin(2*PI*(X/W-0.7*Y/H+T/2))'"
text="drawtext=fontfile=$font:text='draught':fontsize=72:fontcolor=white:borderw=3:bordercolor=black@0.35:x=(w-tw)/2:y=(h-th)/2+18*sin(2*PI*t/4)"
ffmpeg -nostdin -y -loglevel error -f lavfi -i "color=c=black:s=480x270:r=25:d=4,format=rgb24,$bands,$text" \
  -c:v libx264 -preset veryslow -crf 26 -pix_fmt yuv420p -movflags +faststart -map_metadata -1 -fflags +bitexact \
  -flags:v +bitexact "$out"
echo "wrote $out ($(stat -c %s "$out") bytes)"
