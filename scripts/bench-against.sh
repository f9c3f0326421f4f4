#!/usr/bin/env bash
# Times this build's `draught bench` against another draught binary (an older build),
# the two alternating in one run, and prints the median of each binary's per-run median
# frame times for the scenes both know. A scene the old binary cannot load (a preset that
# uses parameters it predates) is skipped and said so, not fatal.
#
#   git worktree add /work/wt-old e9c3f7d && cmake -S /work/wt-old -B /work/wt-old/build \
#     -DCMAKE_BUILD_TYPE=Release -DDRAUGHT_TESTS=OFF && cmake --build /work/wt-old/build --target draught
#   scripts/bench-against.sh /work/wt-old/build/draught [rounds=5] [size=256] [frames=15]
set -euo pipefail
cd "$(dirname "$0")/.."
old=$1
rounds=${2:-5}
size=${3:-256}
frames=${4:-15}
new=build/draught
scenes=${DRAUGHT_BENCH_SCENES:-"pint-lager nonic-stout wine-red pint-lager-fresh-pour"}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
# Which scenes the old binary loads: it exits with an error on the first it cannot.
known=""
for s in $scenes; do
  if "$old" bench -n 1 --sizes 16 --scenes "$s" >/dev/null 2>&1; then
    known="$known $s"
  else
    echo "skipped $s: $old cannot load it" >&2
  fi
done
known=${known# }
[ -n "$known" ] || { echo "the old binary loads none of: $scenes" >&2; exit 1; }
for r in $(seq "$rounds"); do
  "$old" bench -n "$frames" --sizes "$size" --scenes "${known// /,}" 2>/dev/null | awk 'NR > 2 {print $1, $3}' >>"$out/old"
  DRAUGHT_DEVICE=software "$new" bench -n "$frames" --sizes "$size" --scenes "${known// /,}" 2>/dev/null |
    awk 'NR > 2 {print $1, $3}' >>"$out/new"
done
median() { sort -n | awk '{v[NR] = $1} END {print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2}'; }
printf "%-24s %12s %12s %8s   (%d rounds, %dx%d, %d frames each, medians of medians)\n" scene "old ms" "new ms" "new/old" "$rounds" "$size" "$size" "$frames"
for s in $known; do
  o=$(awk -v s="$s" '$1 == s {print $2}' "$out/old" | median)
  n=$(awk -v s="$s" '$1 == s {print $2}' "$out/new" | median)
  printf "%-24s %12.2f %12.2f %8.2f\n" "$s" "$o" "$n" "$(echo "$n / $o" | bc -l)"
done
