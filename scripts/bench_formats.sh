#!/bin/bash
# The writers (every stage on all cores): the 1M icosphere, every edge, view
# 1,1.3,1.7, whole process to each format (SVG, PDF, PNG at 150 dpi, DXF, exact JSON) with
# --threads 1 and 2 in alternating pairs (see bench_threads.sh for why alternating). Reports
# per format the median wall time, the output stage's median (--timings: the 2D stage and the
# writer), its 1 -> 2 thread ratio, the peak memory and the file's size. Writes
# build/bench/formats.md.
# Usage: scripts/bench_formats.sh [PAIRS]   (default 3 pairs)
set -euo pipefail
ROOT=$(cd "$(dirname "$0")/.." && pwd)
BUILD=${HLR_BUILD:-$ROOT/build}
OUT=$BUILD/bench
PAIRS=${1:-3}
[ -x "$BUILD/hlr" ] || { echo "bench_formats: build first (scripts/setup.sh)" >&2; exit 1; }
command -v /usr/bin/time >/dev/null || { echo "bench_formats: needs GNU time (apt install time)" >&2; exit 1; }
mkdir -p "$OUT/meshes"
MESH=$OUT/meshes/sphere1m.off
[ -s "$MESH" ] || "$BUILD/benchmarks/gen_mesh" sphere 224 > "$MESH"
LOG=$OUT/formats.log
: > "$LOG"
for f in svg pdf png dxf json; do
  for i in $(seq "$PAIRS"); do
    order="1 2"
    [ $((i % 2)) = 1 ] && order="2 1"
    for t in $order; do
      /usr/bin/time -f "TIME %e MEM %M" "$BUILD/hlr" render "$MESH" --view 1,1.3,1.7 --edges all --threads "$t" --timings \
        -o "$OUT/formats.$f" 2> "$OUT/formats.run" > /dev/null
      echo "$f $i $t $(stat -c %s "$OUT/formats.$f") $(grep '^TIME' "$OUT/formats.run") $(grep '^timings' "$OUT/formats.run")" >> "$LOG"
    done
  done
done
python3 - "$LOG" "$PAIRS" > "$OUT/formats.md" <<'PY'
import re, statistics, sys
log, pairs = sys.argv[1], int(sys.argv[2])
rows = {}
for line in open(log):
    f, i, t, size = line.split()[:4]
    wall = float(re.search(r"TIME ([0-9.]+)", line).group(1))
    mem = int(re.search(r"MEM ([0-9]+)", line).group(1)) / 1024
    out = float(re.search(r"output ([0-9.]+) s", line).group(1))
    rows.setdefault(f, {}).setdefault(int(t), []).append((wall, out, mem, int(size)))
print("# The writers, 1M icosphere, every edge, view 1,1.3,1.7 (%d alternating pairs)" % pairs)
print()
print("| format | wall s, 2 threads (1 thread) | output stage s, 2 threads (1 thread) | output 1 -> 2 threads | peak MB | file MB |")
print("|---|---|---|---|---|---|")
for f in ("svg", "pdf", "png", "dxf", "json"):
    one, two = rows[f][1], rows[f][2]
    med = lambda xs, k: statistics.median(x[k] for x in xs)
    print("| %s | %.2f (%.2f) | %.2f (%.2f) | %.2fx | %.0f | %.2f |" % (
        f.upper(), med(two, 0), med(one, 0), med(two, 1), med(one, 1), med(one, 1) / med(two, 1),
        max(x[2] for x in two + one), two[0][3] / 1e6))
PY
cat "$OUT/formats.md"
