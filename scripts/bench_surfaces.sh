#!/usr/bin/env bash
# Visible-surfaces benchmark: whole `hlr render` runs to SVG, the line drawing of every edge
# (`--edges all`, the lines the surfaces are made from) against `--surfaces`, best of 3 in
# alternating runs (and `--method weiler-atherton` on the small scene), on 3,200 random
# triangles (edges about 0.1 in the unit cube, coordinates k/1024: `gen_mesh triangles`),
# CGAL's fandisk, couplingdown and bunny00, and icospheres of 100k and 1M triangles; view
# 1,1.3,1.7. Per run: wall time and peak memory (GNU time), the surfaces step's stages
# (--timings); the course's Weiler–Atherton against the fast route on 200 random triangles.
# Writes build/bench/surfaces.md.
# Usage: scripts/bench_surfaces.sh [--quick] [--peer]   (--quick: skip the 1M sphere; --peer:
# also build and run CGAL's exact Envelope_3 on the 3,200 triangles, benchmarks/envelope3_peer.cpp)
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BUILD="${HLR_BUILD_DIR:-$ROOT/build}"
HLR="$BUILD/hlr"
GEN="$BUILD/benchmarks/gen_mesh"
OUT="$BUILD/bench"
QUICK=0
PEER=0
for arg in "$@"; do
  case "$arg" in
    --quick) QUICK=1 ;;
    --peer) PEER=1 ;;
    *) echo "bench_surfaces: unknown option $arg" >&2; exit 2 ;;
  esac
done
[ -x "$HLR" ] && [ -x "$GEN" ] || { echo "bench_surfaces: build first (scripts/setup.sh)" >&2; exit 1; }
command -v /usr/bin/time >/dev/null || { echo "bench_surfaces: needs GNU time (apt install time)" >&2; exit 1; }
MESHES="$("$ROOT/scripts/extract_corpus.sh")"
mkdir -p "$OUT/meshes"
gen() { [ -s "$OUT/meshes/$1.off" ] || "$GEN" "${@:2}" > "$OUT/meshes/$1.off"; echo "$OUT/meshes/$1.off"; }
inputs=("$(gen triangles3200 triangles 3200 1)" "$MESHES/fandisk.off" "$MESHES/couplingdown.off" "$MESHES/bunny00.off"
        "$(gen sphere100k sphere 71)")
[ "$QUICK" = 0 ] && inputs+=("$(gen sphere1m sphere 224)")
run() {  # prints "wall_s peak_MB" and leaves --timings in $OUT/t.err
  /usr/bin/time -f "%e %M" -o "$OUT/time.txt" "$HLR" render "$@" --view 1,1.3,1.7 --timings -o "$OUT/out.svg" 2> "$OUT/t.err" >/dev/null
  read -r wall kb < "$OUT/time.txt"
  echo "$wall $((kb / 1024))"
}
report="$OUT/surfaces.md"
{
  echo "# hlr render --surfaces benchmark ($(date -u +%Y-%m-%d), $(nproc) cores)"
  echo
  echo "| mesh | faces | lines (\`--edges all\`): wall s, peak MB | surfaces: wall s, peak MB | ratio | filled polygons (one per colour region) | surfaces step s (clean-up, points, arrangement, triangles, probes, regions) |"
  echo "|---|---|---|---|---|---|---|"
  for m in "${inputs[@]}"; do
    name="$(basename "$m" .off)"
    faces="$(awk 'NR==2{print $2; exit}' "$m")"
    lw=999; sw=999
    for rep in 1 2 3; do  # best of 3, the two products alternating
      read -r w mb < <(run "$m" --edges all)
      awk -v a="$w" -v b="$lw" 'BEGIN{exit !(a < b)}' && { lw=$w; lm=$mb; }
      read -r w mb < <(run "$m" --surfaces)
      awk -v a="$w" -v b="$sw" 'BEGIN{exit !(a < b)}' && { sw=$w; sm=$mb; }
    done
    line="$(grep 'timings: surfaces' "$OUT/t.err" || true)"
    polys="$(echo "$line" | sed -n 's/.*fills \([0-9]*\).*/\1/p')"
    step="$(echo "$line" | sed -n 's/timings: surfaces \([0-9.]*\) s.*(clean-up \([0-9.]*\) s, points \([0-9.]*\) s, arrangement \([0-9.]*\) s, triangles \([0-9.]*\) s, probes \([0-9.]*\) s, regions \([0-9.]*\) s).*/\1 (\2, \3, \4, \5, \6, \7)/p')"
    echo "| $name | $faces | $lw, $lm | $sw, $sm | $(awk -v a="$sw" -v b="$lw" 'BEGIN{printf "%.1fx", a / b}') | $polys | $step |"
  done
  echo
  small="$(gen triangles200 triangles 200 1)"
  read -r fw fm < <(run "$small" --surfaces)
  read -r ww wm < <(run "$small" --method weiler-atherton)
  echo "200 random triangles: the fast route $fw s ($fm MB), the course's Weiler–Atherton $ww s ($wm MB)."
  if [ "$PEER" = 1 ]; then
    cmake --build "$BUILD" --target envelope3_peer -j "$(nproc)" >/dev/null
    peer="$(/usr/bin/time -f "%e %M" -o "$OUT/time.txt" "$BUILD/benchmarks/envelope3_peer" "$OUT/meshes/triangles3200.off" 1,1.3,1.7)"
    read -r pw pk < "$OUT/time.txt"
    "$HLR" render "$OUT/meshes/triangles3200.off" --surfaces --view 1,1.3,1.7 --timings -o "$OUT/out.json" 2> "$OUT/t.err" >/dev/null
    ours="$(grep 'timings: surfaces' "$OUT/t.err")"
    oe="$(echo "$ours" | sed -n 's/.*arrangement edges \([0-9]*\).*/\1/p')"
    op="$(echo "$ours" | sed -n 's/.*polygons \([0-9]*\).*/\1/p')"
    pe="$(echo "$peer" | sed -n 's/.*, edges \([0-9]*\).*/\1/p')"
    pp="$(echo "$peer" | sed -n 's/.*(covered \([0-9]*\)).*/\1/p')"
    verdict="the same"
    [ "$oe" = "$pe" ] && [ "$op" = "$pp" ] || verdict="DIFFERENT"
    echo
    echo "CGAL Envelope_3 (Epeck), the same 3,200 triangles and view: $peer; whole process $pw s, $((pk / 1024)) MB."
    echo "Cells: CGAL's diagram has $pp covered faces and $pe edges, ours $op visible polygons (per face) and $oe arrangement edges: $verdict."
  fi
} > "$report"
cat "$report"
