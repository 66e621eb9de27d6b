#!/usr/bin/env bash
# Priority-list benchmark: whole `hlr render` runs to SVG with `--method priority`
# against `--surfaces` (the exact visible-surface route), on the three-stick cycle, 3,200
# random triangles (`gen_mesh triangles`), CGAL's fandisk, couplingdown and bunny00, and the
# 100k icosphere; view 1,1.3,1.7 (the scene's own view for the sticks). Per run: wall time and
# peak memory (GNU time); for the priority list its own time, polygons, parts painted, pairs
# put to the tests, swaps, cyclic overlaps and cuts (--timings). Writes build/bench/priority.md.
# Usage: scripts/bench_priority.sh
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BUILD="${HLR_BUILD_DIR:-$ROOT/build}"
HLR="$BUILD/hlr"
GEN="$BUILD/benchmarks/gen_mesh"
OUT="$BUILD/bench"
[ -x "$HLR" ] && [ -x "$GEN" ] || { echo "bench_priority: build first (scripts/setup.sh)" >&2; exit 1; }
command -v /usr/bin/time >/dev/null || { echo "bench_priority: needs GNU time (apt install time)" >&2; exit 1; }
MESHES="$("$ROOT/scripts/extract_corpus.sh")"
mkdir -p "$OUT/meshes"
gen() { [ -s "$OUT/meshes/$1.off" ] || "$GEN" "${@:2}" > "$OUT/meshes/$1.off"; echo "$OUT/meshes/$1.off"; }
inputs=("$ROOT/data/three_sticks.yaml" "$(gen triangles3200 triangles 3200 1)" "$MESHES/fandisk.off" "$MESHES/couplingdown.off"
        "$MESHES/bunny00.off" "$(gen sphere100k sphere 71)")
run() {  # prints "wall_s peak_MB" and leaves --timings in $OUT/t.err
  local view=(--view 1,1.3,1.7)
  case "$1" in *.yaml) view=() ;; esac
  /usr/bin/time -f "%e %M" -o "$OUT/time.txt" "$HLR" render "$@" "${view[@]}" --timings -o "$OUT/out.svg" 2> "$OUT/t.err" >/dev/null
  read -r wall kb < "$OUT/time.txt"
  echo "$wall $((kb / 1024))"
}
report="$OUT/priority.md"
{
  echo "# hlr render --method priority benchmark ($(date -u +%Y-%m-%d), $(nproc) cores)"
  echo
  echo "| scene | faces | --surfaces: wall s, peak MB (step s) | --method priority: wall s, peak MB | priority list s | polygons -> painted | pairs tested | swaps | cycles | cuts |"
  echo "|---|---|---|---|---|---|---|---|---|---|"
  for m in "${inputs[@]}"; do
    name="$(basename "${m%.*}")"
    faces="$(grep -o 'timings: faces [0-9]*' "$OUT/t.err" 2>/dev/null | head -1 || true)"
    read -r sw sm < <(run "$m" --surfaces)
    sstep="$(sed -n 's/timings: surfaces \([0-9.]*\) s.*/\1/p' "$OUT/t.err")"
    faces="$(sed -n 's/timings: faces \([0-9]*\),.*/\1/p' "$OUT/t.err")"
    read -r pw pm < <(run "$m" --method priority)
    line="$(grep 'timings: priority list' "$OUT/t.err")"
    f() { echo "$line" | sed -n "s/.*$1 \\([0-9.]*\\).*/\\1/p"; }
    echo "| $name | $faces | $sw, $sm ($sstep) | $pw, $pm | $(f 'priority list') | $(f polygons) -> $(f painted) | $(f pairs) | $(f swaps) | $(f cycles) | $(f cuts) |"
  done
} > "$report"
cat "$report"
