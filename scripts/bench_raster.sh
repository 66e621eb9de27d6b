#!/usr/bin/env bash
# Speed of `hlr raster`: the four image-space algorithms on generated spheres and
# CGAL's meshes at 1024x1024, whole process and stages (--timings), and Whitted ray tracing of
# the glass demo. Usage: scripts/bench_raster.sh [BUILD_DIR] (default build). Writes
# BUILD/bench/raster.md.
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD="${1:-build}"
HLR="$BUILD/hlr"
GEN="$BUILD/benchmarks/gen_mesh"
OUT="$BUILD/bench"
MESHES="$BUILD/corpus/meshes"
[ -x "$HLR" ] && [ -x "$GEN" ] || { echo "bench_raster: build first (scripts/setup.sh)" >&2; exit 1; }
mkdir -p "$OUT/meshes"
gen() { [ -s "$OUT/meshes/$1.off" ] || "$GEN" "${@:2}" > "$OUT/meshes/$1.off"; echo "$OUT/meshes/$1.off"; }
inputs=()
for m in fandisk bunny00; do [ -s "$MESHES/$m.off" ] && inputs+=("$MESHES/$m.off"); done
inputs+=("$(gen sphere100k sphere 71)")
[ "${QUICK:-0}" = 1 ] || inputs+=("$(gen sphere1m sphere 224)")
{
  echo "| mesh | algorithm | whole process | facing | raster scene | visibility | shading | peak memory |"
  echo "|---|---|---|---|---|---|---|---|"
  for f in "${inputs[@]}"; do
    for a in zbuffer scanline warnock raytrace; do
      log=$( { /usr/bin/time -f "TIME %e %M" "$HLR" raster "$f" --view 1,1.3,1.7 --size 1024x1024 --algorithm "$a" --timings -o "$OUT/raster.png"; } 2>&1 )
      t=$(echo "$log" | awk '/^TIME/{print $2}'); mem=$(echo "$log" | awk '/^TIME/{printf "%d MB", $3/1024}')
      st=$(echo "$log" | sed -n 's/.*facing \([0-9.]*\) s, raster scene \([0-9.]*\) s, [a-z]* \([0-9.]*\) s, shading \([0-9.]*\) s.*/\1 s | \2 s | \3 s | \4 s/p')
      echo "| $(basename "$f") | $a | $t s | $st | $mem |"
    done
  done
  log=$( { /usr/bin/time -f "TIME %e %M" "$HLR" raster data/glass_demo.yaml --bounces 5 --size 640x400 --timings -o "$OUT/glass.png"; } 2>&1 )
  echo "| glass demo, Whitted depth 5, 640x400 | zbuffer + rays | $(echo "$log" | awk '/^TIME/{print $2}') s | | | | | |"
} | tee "$OUT/raster.md"
