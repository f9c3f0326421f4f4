#!/usr/bin/env bash
# Builds the web page into out/web/ (index.html, page.js, style.css, draught.js,
# draught.wasm) with Debian's Emscripten: offline, no ports. Serve out/web/ over http(s)
# (any static server; `node tests/web/server.mjs` does) and open index.html.
set -euo pipefail
cd "$(dirname "$0")/.."
command -v emcmake >/dev/null || { echo "build-web: emscripten is missing (apt-get install emscripten)" >&2; exit 1; }
# Debian's Emscripten finds its JS tools (acorn) through NODE_PATH.
export NODE_PATH="${NODE_PATH:-/usr/share/nodejs}"
if [ ! -f build-web/CMakeCache.txt ]; then
  emcmake cmake -S apps/web -B build-web -DCMAKE_BUILD_TYPE=Release >/dev/null
fi
cmake --build build-web -j"${JOBS:-$(nproc)}"
total=0
for f in draught.wasm draught.js; do
  raw=$(wc -c <"out/web/$f"); gz=$(gzip -9 -c "out/web/$f" | wc -c); total=$((total + gz))
  echo "build-web: out/web/$f: $raw bytes ($gz gzipped)"
done
echo "build-web: draught.wasm + draught.js gzipped (gzip -9): $total bytes"
