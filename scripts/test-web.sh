#!/usr/bin/env bash
# Browser tests of the web page: builds out/web (incrementally), installs the tests' one npm
# package (playwright-core, which drives Debian's chromium; no browser is downloaded) when
# missing, and runs tests/web/run.mjs on SwiftShader's software WebGL2. Ends with
# "web tests: N passed, M failed"; non-zero exit on any failure. Arguments go to run.mjs
# (a substring selects tests by name).
set -uo pipefail
cd "$(dirname "$0")/.."

fail_setup() {
  echo "test-web: $*" >&2
  echo "web tests: 0 passed, 1 failed"
  exit 1
}

if command -v emcmake >/dev/null; then
  # The build's log is shown only when it fails: the tests' lines are what a log's tail
  # should show.
  build_log=$(mktemp)
  if ! scripts/build-web.sh >"$build_log" 2>&1; then
    cat "$build_log"; rm -f "$build_log"
    fail_setup "the web build failed"
  fi
  grep '^build-web:' "$build_log"; rm -f "$build_log"
elif [ -f out/web/draught.wasm ]; then
  echo "test-web: emscripten is not installed; testing the existing out/web" >&2
else
  fail_setup "emscripten is not installed (apt-get install emscripten) and out/web/ is not built"
fi

command -v node >/dev/null || fail_setup "node is missing (apt-get install nodejs npm)"
CHROMIUM="${CHROMIUM:-/usr/bin/chromium}"
[ -x "$CHROMIUM" ] || fail_setup "$CHROMIUM is missing (apt-get install chromium)"
export CHROMIUM

if [ ! -f tests/web/node_modules/playwright-core/package.json ]; then
  echo "test-web: installing playwright-core (npm ci)" >&2
  (cd tests/web && { npm ci --no-audit --no-fund --loglevel=error || npm install --no-audit --no-fund --loglevel=error; }) \
    || fail_setup "npm could not install playwright-core"
fi

cd tests/web && exec node run.mjs "$@"
