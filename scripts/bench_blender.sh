#!/bin/bash
# Feature lines against Blender Line Art (the inexact peer), in the same run: silhouettes,
# creases over 40 degrees, intersections and hidden lines, view 1,1.3,1.7, 2 threads. Our
# time is the whole process to SVG; Blender's is Line Art's evaluation alone (its own mesh
# import and start-up are left out, benchmarks/blender_lineart.py). Needs `blender` (Debian's
# package: apt-get install blender); writes build/bench/blender.md.
# Usage: scripts/bench_blender.sh [MESH.off ...]  (default: bunny00 and the 1M icosphere)
set -euo pipefail
ROOT=$(cd "$(dirname "$0")/.." && pwd)
BUILD=${HLR_BUILD:-$ROOT/build}
OUT=$BUILD/bench
mkdir -p "$OUT/meshes"
command -v blender >/dev/null || { echo "bench_blender: blender is not installed (apt-get install blender)" >&2; exit 1; }
if [ $# -eq 0 ]; then
  [ -f "$OUT/meshes/sphere1m.off" ] || "$BUILD/gen_mesh" sphere 224 > "$OUT/meshes/sphere1m.off"
  set -- "$BUILD/corpus/meshes/bunny00.off" "$OUT/meshes/sphere1m.off"
fi
runs=${RUNS:-3}
{
  echo "| mesh | faces | exact-hlr, whole process (min-max of $runs) | Blender Line Art, compute alone (min-max of $runs) | ratio (medians) |"
  echo "|---|---|---|---|---|"
} > "$OUT/blender.md"
for mesh in "$@"; do
  ours=(); theirs=()
  # Ours first, then Blender's: Blender's import churns gigabytes, and the machine hands out fresh
  # memory slowly for a while after (a run of ours right after one of Blender's took twice as long).
  for i in $(seq "$runs"); do
    s=$( { /usr/bin/time -f "%e" "$BUILD/hlr" render "$mesh" --view 1,1.3,1.7 --edges feature --crease 40 --hidden dashed \
          --threads 2 -o "$OUT/blender_ours.svg" ; } 2>&1 | tail -1)
    ours+=("$s")
  done
  for i in $(seq "$runs"); do
    b=$(blender -b -t 2 --factory-startup --python "$ROOT/benchmarks/blender_lineart.py" -- "$mesh" 1,1.3,1.7 40 2>&1 |
        sed -n 's/^lineart compute: \([0-9.]*\) s.*/\1/p')
    theirs+=("$b")
  done
  faces=$(sed -n '2p' "$mesh" | awk '{print $2}')
  python3 - "$(basename "$mesh")" "$faces" "${ours[*]}" "${theirs[*]}" >> "$OUT/blender.md" <<'PY'
import statistics, sys
name, faces, ours, theirs = sys.argv[1], sys.argv[2], [float(x) for x in sys.argv[3].split()], [float(x) for x in sys.argv[4].split()]
mo, mt = statistics.median(ours), statistics.median(theirs)
print(f"| {name} | {faces} | {min(ours):.2f}-{max(ours):.2f} s | {min(theirs):.2f}-{max(theirs):.2f} s | {mt / mo:.1f}x faster |")
PY
done
cat "$OUT/blender.md"
