#!/usr/bin/env bash
# Re-renders every golden image (tests/golden/*.png) from the current code, and copies
# them to build/golden-diff/ too. Deliberate: look at every image before committing.
set -euo pipefail
cd "$(dirname "$0")/.."
cmake --build build -j"$(nproc)" --target gpu_tests
DRAUGHT_DEVICE=software ./build/tests/gpu_tests --gtest_filter='Scenes/Golden.*' --bless
echo "Blessed. Now open each tests/golden/*.png and judge it before you commit."
