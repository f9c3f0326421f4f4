#!/usr/bin/env bash
# Builds and runs every test, ending with CTest's summary line:
#  1. the unit suite (core, preset fuzzing included) under AddressSanitizer + UBSan,
#  2. everything through CTest: unit, GPU probes and goldens on Mesa llvmpipe, CLI, docs.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/deps.sh
scripts/build.sh

echo "== unit tests under AddressSanitizer + UBSan =="
[ -f build-asan/CMakeCache.txt ] || cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=Debug -DDRAUGHT_SANITIZE=ON >/dev/null
cmake --build build-asan -j"$(nproc)" --target unit_tests
UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1 ASAN_OPTIONS=detect_leaks=1 \
  ./build-asan/tests/unit_tests --gtest_brief=1

echo "== all tests =="
ctest --test-dir build --output-on-failure -j"$(nproc)"
