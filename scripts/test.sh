#!/usr/bin/env bash
# Builds and runs every test (unit, GPU probes and goldens on Mesa llvmpipe, CLI),
# ending with CTest's summary line.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/deps.sh
scripts/build.sh
ctest --test-dir build --output-on-failure -j"$(nproc)"
