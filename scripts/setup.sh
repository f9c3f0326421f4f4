#!/usr/bin/env bash
# The main job on a fresh Debian 12 machine: install what is missing, build, and render
# the default preset to out/draught.png (no display, no GPU needed).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/deps.sh
scripts/build.sh
./build/draught render --verbose -o out/draught.png
