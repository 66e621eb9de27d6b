#!/usr/bin/env bash
# The largest row: the 10M-triangle icosphere (benchmarks/gen_mesh sphere 707, 7 fixed
# decimals), every edge, view 1,1.3,1.7, to SVG. Each hlr given (e.g. a build before and after a
# change) runs in alternating runs, best of 3 wall seconds each (GNU time), with peak memory
# and the stages hlr reports (--timings); the SVGs of all builds must be the same bytes.
# Writes build/bench/large.md. The mesh (410 MB) is made once in build/bench/meshes.
# Usage: scripts/bench_large.sh [HLR ...]   (default: build/hlr)
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BUILD="${HLR_BUILD_DIR:-$ROOT/build}"
OUT="$BUILD/bench"
GEN="$BUILD/benchmarks/gen_mesh"
[ $# -gt 0 ] || set -- "$BUILD/hlr"
for h in "$@"; do [ -x "$h" ] || { echo "bench_large: $h is not a program" >&2; exit 1; }; done
[ -x "$GEN" ] || { echo "bench_large: build benchmarks/gen_mesh first (make gen_mesh)" >&2; exit 1; }
command -v /usr/bin/time >/dev/null || { echo "bench_large: needs GNU time (apt install time)" >&2; exit 1; }
mkdir -p "$OUT/meshes"
MESH="$OUT/meshes/sphere10m.off"
[ -s "$MESH" ] || "$GEN" sphere 707 > "$MESH"
declare -A best_wall best_line
for round in 1 2 3; do
  k=0
  for h in "$@"; do
    k=$((k + 1))
    log="$OUT/large_$k.log"
    /usr/bin/time -f "TIME %e %M" "$h" render "$MESH" --edges all --view 1,1.3,1.7 --timings -o "$OUT/large_$k.svg" 2> "$log" > /dev/null
    wall=$(awk '/^TIME/ {print $2}' "$log")
    mb=$(awk '/^TIME/ {printf "%.0f", $3 / 1024}' "$log")
    s=$(grep '^timings' "$log")
    f() { echo "$s" | sed -n "s/.*$1 \([0-9.]*\) s.*/\1/p"; }
    line="| $h | $wall | $mb | $(f load) | $(f setup) | $(f intersections) | $(f visibility) | $(f output) |"
    echo "round $round: $line"
    if [ -z "${best_wall[$k]:-}" ] || awk -v a="$wall" -v b="${best_wall[$k]}" 'BEGIN {exit !(a < b)}'; then
      best_wall[$k]=$wall
      best_line[$k]=$line
    fi
  done
done
same=yes
for k in $(seq 2 $#); do cmp -s "$OUT/large_1.svg" "$OUT/large_$k.svg" || same=no; done
report="$OUT/large.md"
{
  echo "# 10M-triangle icosphere, every edge ($(date -u +%Y-%m-%d), $(nproc) cores, $(awk '/MemTotal/ {printf "%.0f GiB", $2 / 1048576}' /proc/meminfo); best of 3, alternating)"
  echo
  echo "| hlr | wall s | peak MB | load s | setup s | intersections s | visibility s | output s |"
  echo "|---|---|---|---|---|---|---|---|"
  for k in $(seq 1 $#); do echo "${best_line[$k]}"; done
  echo
  echo "SVGs the same bytes: $same"
} > "$report"
cat "$report"
[ "$same" = yes ]
