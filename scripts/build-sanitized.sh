#!/usr/bin/env bash
# Builds fuzz/ into build-fuzz/: the loaders' libFuzzer targets and the unit suite, both
# on one core library instrumented with AddressSanitizer + UBSan (clang). CTest runs it
# as the `sanitized_build` fixture, beside the browser tests, before the sanitized unit
# shards and `fuzz_loaders`.
set -euo pipefail
cd "$(dirname "$0")/.."
if ! command -v clang++ >/dev/null; then
  echo "build-sanitized: clang++ not found (scripts/deps.sh installs clang and libclang-rt-14-dev)"
  exit 1
fi
[ -f build-fuzz/CMakeCache.txt ] || cmake -S fuzz -B build-fuzz -DCMAKE_CXX_COMPILER=clang++ >/dev/null
cmake --build build-fuzz -j"$(nproc)"
