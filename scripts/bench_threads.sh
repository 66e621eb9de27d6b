#!/bin/bash
# Thread scaling: the 1M icosphere rendered with --threads 1 and --threads 2 in
# alternating pairs (one pair 1 then 2, the next 2 then 1, so that neither count always runs
# after the other), every edge and feature lines, whole process to SVG. Reports per job the
# medians, the ratio of the medians, the median of the pairs' ratios, and each stage's ratio
# of its best times (--timings; stages under 50 ms left out). Writes build/bench/threads.md.
#
# On this project's VM the host backs guest memory lazily and takes back what the guest freed a
# few seconds earlier, so a run that follows a pause or a long run (a one-thread run lasts two
# seconds) first waits for the host to back its pages again: 0.1-0.3 s, on one and two threads
# alike. The runs go back to back; touching memory in another process first made it worse
# (what it freed was taken back just as the run began).
# Usage: scripts/bench_threads.sh [PAIRS]   (default 8 pairs)
set -euo pipefail
ROOT=$(cd "$(dirname "$0")/.." && pwd)
BUILD=${HLR_BUILD:-$ROOT/build}
OUT=$BUILD/bench
PAIRS=${1:-8}
[ -x "$BUILD/hlr" ] || { echo "bench_threads: build first (scripts/setup.sh)" >&2; exit 1; }
command -v /usr/bin/time >/dev/null || { echo "bench_threads: needs GNU time (apt install time)" >&2; exit 1; }
mkdir -p "$OUT/meshes"
MESH=$OUT/meshes/sphere1m.off
[ -s "$MESH" ] || "$BUILD/benchmarks/gen_mesh" sphere 224 > "$MESH"
LOG=$OUT/threads.log
: > "$LOG"
for job in all feature; do
  args=(--edges all)
  [ "$job" = feature ] && args=(--edges feature --crease 40 --hidden dashed)
  for i in $(seq "$PAIRS"); do
    order="1 2"
    [ $((i % 2)) = 1 ] && order="2 1"
    for t in $order; do
      /usr/bin/time -f "TIME %e" "$BUILD/hlr" render "$MESH" --view 1,1.3,1.7 "${args[@]}" --threads "$t" --timings \
        -o "$OUT/threads.svg" 2> "$OUT/threads.run" > /dev/null
      echo "$job $i $t $(grep '^TIME' "$OUT/threads.run") $(grep '^timings' "$OUT/threads.run")" >> "$LOG"
    done
  done
done
python3 - "$LOG" "$PAIRS" > "$OUT/threads.md" <<'PY'
import re, statistics, sys
log, pairs = sys.argv[1], int(sys.argv[2])
runs = {}
for line in open(log):
    job, i, t = line.split()[:3]
    wall = float(re.search(r"TIME ([0-9.]+)", line).group(1))
    stages = {k: float(v) for k, v in re.findall(r"(load|setup|intersections|visibility|output) ([0-9.]+) s", line)}
    runs[(job, int(i), int(t))] = (wall, stages)
print("# Thread scaling, 1M icosphere, view 1,1.3,1.7 (%d alternating pairs)" % pairs)
print()
print("| job | 1 thread, median (min-max) | 2 threads, median (min-max) | ratio of medians | median of pair ratios | stages, best of each: 1 -> 2 threads |")
print("|---|---|---|---|---|---|")
for job, name in (("all", "every edge"), ("feature", "feature lines, hidden dashed")):
    one = [runs[(job, i, 1)] for i in range(1, pairs + 1)]
    two = [runs[(job, i, 2)] for i in range(1, pairs + 1)]
    a, b = [w for w, _ in one], [w for w, _ in two]
    q = [x / y for x, y in zip(a, b)]
    st = []
    for k in ("load", "setup", "intersections", "visibility", "output"):
        s1, s2 = min(s[k] for _, s in one), min(s[k] for _, s in two)
        if s1 < 0.05: continue  # a few milliseconds: no ratio worth reading
        st.append("%s %.2f -> %.2f (%.2fx)" % (k, s1, s2, s1 / s2))
    print("| %s | %.2f s (%.2f-%.2f) | %.2f s (%.2f-%.2f) | %.2fx | %.2fx | %s |" % (
        name, statistics.median(a), min(a), max(a), statistics.median(b), min(b), max(b),
        statistics.median(a) / statistics.median(b), statistics.median(q), ", ".join(st)))
print()
print("Pairs (1 thread / 2 threads, s):")
print()
for job in ("all", "feature"):
    print("- %s: %s" % (job, " ".join("%.2f/%.2f" % (runs[(job, i, 1)][0], runs[(job, i, 2)][0]) for i in range(1, pairs + 1))))
PY
cat "$OUT/threads.md"
