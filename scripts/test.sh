#!/usr/bin/env bash
# Builds and runs every test through CTest, ending with its summary line: unit, GPU
# probes and goldens on Mesa llvmpipe, CLI, docs, the browser tests, and the sanitized
# build (clang, ASan + UBSan, in build-fuzz/) with the unit suite's shards and the fuzz
# targets on it.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/deps.sh
scripts/build.sh

echo "== all tests (at ${SECONDS} s) =="
ctest --test-dir build --output-on-failure -j"$(nproc)"
