#!/usr/bin/env bash
# Builds and runs every test, ending with CTest's summary line:
#  1. the unit suite (core, preset fuzzing included) under AddressSanitizer + UBSan, built
#     by clang in build-fuzz/ beside the fuzz targets (one instrumented core serves both),
#  2. everything through CTest: unit, GPU probes and goldens on Mesa llvmpipe, CLI, docs,
#     the fuzz targets (already built), the browser tests.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/deps.sh
scripts/build.sh

echo "== unit tests under AddressSanitizer + UBSan (at ${SECONDS} s) =="
[ -f build-fuzz/CMakeCache.txt ] || cmake -S fuzz -B build-fuzz -DCMAKE_CXX_COMPILER=clang++ >/dev/null
cmake --build build-fuzz -j"$(nproc)"
# One shard a core (gtest's own sharding): the instrumented suite is single-threaded.
shards="$(nproc)"
pids=()
for ((i = 0; i < shards; ++i)); do
  GTEST_TOTAL_SHARDS="$shards" GTEST_SHARD_INDEX="$i" \
  UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1 ASAN_OPTIONS=detect_leaks=1 \
    ./build-fuzz/unit_tests --gtest_brief=1 > "build-fuzz/unit-shard-$i.log" 2>&1 &
  pids+=("$!")
done
asan_failed=0
for ((i = 0; i < shards; ++i)); do
  wait "${pids[$i]}" || asan_failed=1
  echo "-- shard $((i + 1)) of $shards"
  cat "build-fuzz/unit-shard-$i.log"
done
[ "$asan_failed" = 0 ] || { echo "unit tests under AddressSanitizer + UBSan failed"; exit 1; }

echo "== all tests (at ${SECONDS} s) =="
ctest --test-dir build --output-on-failure -j"$(nproc)"
