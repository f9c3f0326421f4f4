#!/usr/bin/env bash
# Builds and runs every test, ending with CTest's summary line:
#  1. the unit suite (core, preset fuzzing included) under AddressSanitizer + UBSan,
#  2. everything through CTest: unit, GPU probes and goldens on Mesa llvmpipe, CLI, docs.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/deps.sh
scripts/build.sh

echo "== unit tests under AddressSanitizer + UBSan (at ${SECONDS} s) =="
[ -f build-asan/CMakeCache.txt ] || cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=Debug -DDRAUGHT_SANITIZE=ON >/dev/null
cmake --build build-asan -j"$(nproc)" --target unit_tests
# One shard a core (gtest's own sharding): the instrumented suite is single-threaded.
shards="$(nproc)"
pids=()
for ((i = 0; i < shards; ++i)); do
  GTEST_TOTAL_SHARDS="$shards" GTEST_SHARD_INDEX="$i" \
  UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1 ASAN_OPTIONS=detect_leaks=1 \
    ./build-asan/tests/unit_tests --gtest_brief=1 > "build-asan/unit-shard-$i.log" 2>&1 &
  pids+=("$!")
done
asan_failed=0
for ((i = 0; i < shards; ++i)); do
  wait "${pids[$i]}" || asan_failed=1
  echo "-- shard $((i + 1)) of $shards"
  cat "build-asan/unit-shard-$i.log"
done
[ "$asan_failed" = 0 ] || { echo "unit tests under AddressSanitizer + UBSan failed"; exit 1; }

echo "== all tests (at ${SECONDS} s) =="
ctest --test-dir build --output-on-failure -j"$(nproc)"
