#!/usr/bin/env bash
# Re-renders golden images (tests/golden/*.png) from the current code, and copies them
# to build/golden-diff/ too. Deliberate: look at every image before committing.
#
#   scripts/bless-goldens.sh                  # every golden
#   scripts/bless-goldens.sh flight flight_angle   # only these (new goldens)
set -euo pipefail
cd "$(dirname "$0")/.."
filter='Scenes/Golden.*'
if [ $# -gt 0 ]; then
  filter=""
  for name in "$@"; do filter="${filter:+$filter:}Scenes/Golden.MatchesBlessedImage/$name"; done
fi
cmake --build build -j"$(nproc)" --target gpu_tests
DRAUGHT_DEVICE=software ./build/tests/gpu_tests --gtest_filter="$filter" --bless
echo "Blessed. Now open each image written above and judge it before you commit."
