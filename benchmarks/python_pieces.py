#!/usr/bin/env python3
"""What a Python user pays to read a drawing: the render, the pieces as numpy arrays, the pieces
with exact Fractions, and the CLI's JSON for comparison; best of N runs, in one process per
module folder (the package in build/python, or an older module's folder), alternating.

    /usr/bin/python3 benchmarks/python_pieces.py MESH [MODULE_DIR ...] [--runs 3]

Prints one line per module folder: seconds for render(MESH, edges="all"), arrays() (where the
module has it), segments (every piece's Fractions) and json().
"""
import subprocess
import sys

CHILD = r"""
import sys, time
sys.path.insert(0, sys.argv[1])
import exact_hlr
mesh, runs = sys.argv[2], int(sys.argv[3])
best = {}
def keep(name, t):
    best[name] = min(best.get(name, 1e9), t)
for _ in range(runs):
    t = time.perf_counter(); d = exact_hlr.render(mesh, edges="all"); keep("render", time.perf_counter() - t)
    if hasattr(d, "arrays"):
        t = time.perf_counter(); a = d.arrays(); keep("arrays", time.perf_counter() - t)
    t = time.perf_counter(); s = d.segments; keep("fractions", time.perf_counter() - t)
    t = time.perf_counter(); j = d.json(); keep("json", time.perf_counter() - t)
print(len(s), " ".join(f"{k}={v:.3f}" for k, v in best.items()))
"""


def main(argv):
    runs = 3
    if "--runs" in argv:
        i = argv.index("--runs")
        runs = int(argv[i + 1])
        del argv[i:i + 2]
    mesh, dirs = argv[1], argv[2:] or ["build/python"]
    results = {d: [] for d in dirs}
    for _ in range(runs):  # alternating: each module once per round
        for d in dirs:
            out = subprocess.run([sys.executable, "-c", CHILD, d, mesh, "1"], check=True, capture_output=True, text=True).stdout.split()
            results[d].append((int(out[0]), dict(kv.split("=") for kv in out[1:])))
    for d in dirs:
        pieces = results[d][0][0]
        keys = results[d][0][1].keys()
        best = {k: min(float(r[1][k]) for r in results[d]) for k in keys}
        print(f"{d}: {pieces} pieces, best of {runs}: " + ", ".join(f"{k} {v:.3f} s" for k, v in best.items()))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
