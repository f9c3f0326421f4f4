#!/usr/bin/env bash
# Re-renders golden images (tests/golden/*.png) from the current code, and copies them
# to build/golden-diff/ too. Deliberate: look at every image before committing.
#
#   scripts/bless-goldens.sh                  # every golden
#   scripts/bless-goldens.sh flight flight_angle   # only these (new goldens)
#
# With --references (what scripts/bless-references.sh runs): the path-traced references
# (tests/golden/reference/) of the reference comparisons and of the hot gob's glow
# (CloudGlow, case gob_marver_glow) instead.
set -euo pipefail
cd "$(dirname "$0")/.."
suite='Scenes/Golden' test='MatchesBlessedImage' others=''
done_message="Blessed. Now open each image written above and judge it before you commit."
if [ "${1:-}" = --references ]; then
  shift
  suite='Scenes/ReferenceComparison' test='RegionsAgreeWithinTheirBounds' others='CloudGlow.*'
  done_message="Stored. Read the figures above (and DRAUGHT_COMPARISON_DUMP's pictures where they moved) before you commit."
fi
filter="$suite.*${others:+:$others}"
if [ $# -gt 0 ]; then
  filter=""
  for name in "$@"; do
    if [ -n "$others" ] && [ "$name" = gob_marver_glow ]; then filter="${filter:+$filter:}$others"
    else filter="${filter:+$filter:}$suite.$test/$name"; fi
  done
fi
cmake --build build -j"$(nproc)" --target gpu_tests
# (The environment CTest gives the GPU tests, tests/CMakeLists.txt.)
DRAUGHT_DEVICE=software GALLIVM_PERF=nopt ./build/tests/gpu_tests --gtest_filter="$filter" --bless
echo "$done_message"
