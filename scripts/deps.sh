#!/usr/bin/env bash
# Installs the Debian 12 packages draught needs, skipping those already there
# (idempotent). Uses sudo when not root. clang and libclang-rt-14-dev (its runtime
# libraries, libFuzzer among them) build the fuzz targets (scripts/fuzz.sh) and the unit
# suite under the sanitizers (scripts/test.sh).
set -euo pipefail

packages=(
  g++ cmake make pkg-config
  libglm-dev nlohmann-json3-dev libstb-dev libtinyexr-dev libcli11-dev
  libgtest-dev libbenchmark-dev
  libegl-dev libgles-dev libegl-mesa0 libgl1-mesa-dri
  libsdl2-dev ffmpeg
  libimgui-dev xvfb xauth
  emscripten chromium
  clang libclang-rt-14-dev
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
# Node.js and npm run the browser tests; any install that provides the commands will do
# (Debian's packages, or a newer Node.js that bundles npm).
command -v node >/dev/null || missing+=(nodejs)
command -v npm >/dev/null || missing+=(npm)
if [ ${#missing[@]} -eq 0 ]; then
  echo "deps: all ${#packages[@]} packages present"
  exit 0
fi

echo "deps: installing ${missing[*]}"
sudo_cmd=()
[ "$(id -u)" -eq 0 ] || sudo_cmd=(sudo)
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -qq
"${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
