#!/usr/bin/env bash
# Builds the libFuzzer targets (fuzz/: clang, AddressSanitizer + UBSan) into build-fuzz/
# and runs each for SECONDS (default 60), seeded with the shipped presets and timelines.
#
#   scripts/fuzz.sh [SECONDS]
#
# Exit status: 0 no finding, 1 a finding (the input is saved under build-fuzz/findings/),
# 125 when clang or libFuzzer is missing (CTest counts that as skipped; scripts/deps.sh
# installs them). The corpus grown by each run is kept in build-fuzz/corpus/ for the next.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-60}"

if ! command -v clang++ >/dev/null; then
  echo "fuzz: clang++ not found (scripts/deps.sh installs clang and libclang-rt-14-dev)"
  exit 125
fi
probe="$(mktemp -d)"
trap 'rm -rf "$probe"' EXIT
echo 'extern "C" int LLVMFuzzerTestOneInput(const unsigned char*, unsigned long) { return 0; }' >"$probe/p.cpp"
if ! clang++ -fsanitize=fuzzer,address,undefined "$probe/p.cpp" -o "$probe/p" 2>/dev/null; then
  echo "fuzz: clang++ cannot link libFuzzer (install libclang-rt-14-dev, see scripts/deps.sh)"
  exit 125
fi

[ -f build-fuzz/CMakeCache.txt ] || cmake -S fuzz -B build-fuzz -DCMAKE_CXX_COMPILER=clang++ >/dev/null
targets=(preset timeline hdr_image decal_image video_source point_cloud)
cmake --build build-fuzz -j"$(nproc)" --target "${targets[@]/#/fuzz_}" >/dev/null

declare -A seeds=(
  [preset]="presets/glasses presets/drinks presets/scenes"
  [timeline]="presets/timelines"
  [hdr_image]="fuzz/seeds/hdr_image fuzz/regressions/hdr_image"
  [decal_image]="fuzz/seeds/decal_image fuzz/regressions/decal_image"
  [video_source]="fuzz/seeds/video_source fuzz/regressions/video_source"
  [point_cloud]="fuzz/seeds/point_cloud fuzz/regressions/point_cloud"
)
declare -A dicts=([preset]=fuzz/json.dict [timeline]=fuzz/json.dict [hdr_image]=fuzz/hdr.dict [decal_image]=fuzz/png.dict [video_source]=fuzz/video.dict [point_cloud]=fuzz/ply.dict)
status=0
for target in "${targets[@]}"; do
  corpus="build-fuzz/corpus/$target"
  mkdir -p "$corpus" build-fuzz/findings
  log="build-fuzz/fuzz_$target.log"
  # Findings and timeouts exit 1 (libFuzzer's default 77 would read as "skipped").
  # shellcheck disable=SC2086
  if ./build-fuzz/fuzz_$target "$corpus" ${seeds[$target]} -dict="${dicts[$target]}" -max_total_time="$seconds" \
      -max_len=16384 -timeout=10 -rss_limit_mb=2048 -error_exitcode=1 -timeout_exitcode=1 -print_final_stats=1 \
      -artifact_prefix="build-fuzz/findings/$target-" >"$log" 2>&1; then
    runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log")
    rate=$(sed -n 's/^stat::average_exec_per_sec: *//p' "$log")
    units=$(find "$corpus" -type f | wc -l)
    echo "fuzz_$target: $runs runs in $seconds s ($rate exec/s), corpus $units inputs, no finding"
  else
    status=1
    echo "fuzz_$target: FINDING (log: $log; input: build-fuzz/findings/$target-*)"
    grep -E "^(==[0-9]+==ERROR|SUMMARY|finding:|.*runtime error)" "$log" | head -5 || true
  fi
done
exit $status
