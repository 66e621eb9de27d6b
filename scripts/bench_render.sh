#!/usr/bin/env bash
# Render benchmark: whole `hlr render` runs to SVG on CGAL's meshes (fandisk,
# couplingdown, bunny00, armadillo, refined_elephant) and generated spheres and tori of 10k,
# 100k and 1M triangles, views 1,1.3,1.7 and 0,0,1, `--edges all` and `--edges feature
# --crease 40`. Per run: wall time and peak memory of the process (GNU time), the stage times
# hlr reports (--timings) and the number of segments. Writes build/bench/render.md.
# Usage: scripts/bench_render.sh [--quick]   (--quick: skip the 1M meshes)
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BUILD="${HLR_BUILD_DIR:-$ROOT/build}"
HLR="$BUILD/hlr"
GEN="$BUILD/benchmarks/gen_mesh"
OUT="$BUILD/bench"
QUICK=0
[ "${1:-}" = "--quick" ] && QUICK=1
[ -x "$HLR" ] && [ -x "$GEN" ] || { echo "bench_render: build first (scripts/setup.sh)" >&2; exit 1; }
command -v /usr/bin/time >/dev/null || { echo "bench_render: needs GNU time (apt install time)" >&2; exit 1; }
MESHES="$("$ROOT/scripts/extract_corpus.sh")"
mkdir -p "$OUT/meshes"
gen() { [ -s "$OUT/meshes/$1.off" ] || "$GEN" "${@:2}" > "$OUT/meshes/$1.off"; echo "$OUT/meshes/$1.off"; }
inputs=("$MESHES/fandisk.off" "$MESHES/couplingdown.off" "$MESHES/bunny00.off" "$MESHES/armadillo.off"
        "$MESHES/refined_elephant.off" "$(gen sphere10k sphere 22)" "$(gen sphere100k sphere 71)"
        "$(gen torus10k torus 100 50)" "$(gen torus100k torus 316 158)")
if [ "$QUICK" = 0 ]; then inputs+=("$(gen sphere1m sphere 224)" "$(gen torus1m torus 1000 500)"); fi
report="$OUT/render.md"
{
  echo "# hlr render benchmark ($(date -u +%Y-%m-%d), $(nproc) cores)"
  echo
  echo "| mesh | faces | view | edges | wall s | peak MB | load s | setup s | intersections s | visibility s | output s | segments |"
  echo "|---|---|---|---|---|---|---|---|---|---|---|---|"
} > "$report"
for mesh in "${inputs[@]}"; do
  for view in 1,1.3,1.7 0,0,1; do
    for edges in all feature; do
      args=(--edges "$edges")
      [ "$edges" = feature ] && args+=(--crease 40)
      log="$OUT/last.log"
      /usr/bin/time -f "TIME %e %M" "$HLR" render "$mesh" --view "$view" "${args[@]}" --timings -o "$OUT/out.svg" 2> "$log" >/dev/null
      t=$(grep '^TIME' "$log")
      s=$(grep '^timings' "$log")
      wall=$(echo "$t" | awk '{print $2}')
      mb=$(echo "$t" | awk '{printf "%.0f", $3/1024}')
      f() { echo "$s" | sed -n "s/.*$1 \([0-9.]*\).*/\1/p"; }
      echo "| $(basename "$mesh" .off) | $(f faces) | $view | $edges | $wall | $mb | $(f load) | $(f setup) | $(f intersections) | $(f visibility) | $(f output) | $(f segments) |" >> "$report"
      echo "$(basename "$mesh") $view $edges: ${wall}s ${mb}MB"
    done
  done
done
echo "wrote $report"
