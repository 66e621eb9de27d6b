#!/usr/bin/env bash
# Benchmark of the plotting 2D stage: its cost (exact clean-up, chaining, pen
# order) against the whole render, on the 1M-triangle sphere with --edges all and on CGAL's
# bunny00, fandisk and couplingdown (3/4 view with hidden lines); and what it achieves: strokes
# against the Euler minimum, pen-up travel as chained, after greedy nearest neighbour and after
# 2-opt. Writes build/bench/plot.md.
# Usage: scripts/bench_plot.sh [--quick]   (--quick: skip the 1M sphere)
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BUILD="${HLR_BUILD_DIR:-$ROOT/build}"
HLR="$BUILD/hlr" GEN="$BUILD/benchmarks/gen_mesh" OUT="$BUILD/bench"
[ -x "$HLR" ] && [ -x "$GEN" ] || { echo "bench_plot: build first (scripts/setup.sh)" >&2; exit 1; }
MESHES="$("$ROOT/scripts/extract_corpus.sh")"
mkdir -p "$OUT/meshes"
report="$OUT/plot.md"
{
  echo "# hlr render: the plotting 2D stage ($(date -u +%Y-%m-%d), $(nproc) cores)"
  echo
  echo "| mesh | view | wall s (raw) | wall s | clean-up s | chaining s | ordering s | pieces | end-on | overlap groups | paths (minimum) | pen-up mm: chained / greedy / 2-opt |"
  echo "|---|---|---|---|---|---|---|---|---|---|---|---|"
} > "$report"
run() {  # mesh, view, extra args...
  local mesh="$1" view="$2"
  shift 2
  local t0 t1 t2 s
  t0=$(date +%s.%N)
  "$HLR" render "$mesh" --view "$view" "$@" --raw --quiet -o "$OUT/raw.svg"
  t1=$(date +%s.%N)
  "$HLR" render "$mesh" --view "$view" "$@" --stats --quiet -o "$OUT/plot.svg" 2> "$OUT/stats.log"
  t2=$(date +%s.%N)
  s=$(grep '^stats' "$OUT/stats.log")
  num() { echo "$s" | sed -E "s/.*$1 ([0-9.]+).*/\1/"; }
  printf '| %s | %s | %.2f | %.2f | %s | %s | %s | %s | %s | %s | %s (%s) | %s / %s / %s |\n' "$(basename "$mesh" .off)" "$view" \
    "$(echo "$t1 - $t0" | bc)" "$(echo "$t2 - $t1" | bc)" "$(num 'clean-up')" "$(num 'chaining')" "$(num 'ordering')" \
    "$(num 'pieces')" "$(num 'end-on')" "$(num 'overlap groups')" "$(num 'paths')" "$(num 'minimum')" \
    "$(num 'unordered')" "$(num 'greedy')" "$(num 'pen-up')" >> "$report"
}
for m in bunny00 fandisk couplingdown; do
  run "$MESHES/$m.off" 1,1.3,1.7 --hidden dashed
  run "$MESHES/$m.off" front --hidden dashed
done
if [ "${1:-}" != "--quick" ]; then
  [ -s "$OUT/meshes/sphere1m.off" ] || "$GEN" sphere 224 > "$OUT/meshes/sphere1m.off"
  run "$OUT/meshes/sphere1m.off" 1,1.3,1.7 --edges all
fi
cat "$report"
