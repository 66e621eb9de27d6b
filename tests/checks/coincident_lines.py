#!/usr/bin/env python3
"""Checks of the page merge of coincident lines (algorithms/plot/coincident_lines.hpp) on the
SVGs hlr writes, by a grid of their segments in page mm:

  coincident_lines.py MERGED.SVG EXACT.SVG TOL
    - in MERGED, the visible length that runs within TOL of another visible path (nearly
      parallel, alongside) and the hidden length within TOL of a visible path are each under
      0.1% of their layer class's length;
    - nothing else is lost: every point of EXACT (the same drawing with --merge-tolerance 0)
      lies within 0.26 mm (a quarter pen's tolerance and the dropped ends) of a MERGED path of
      its class or a higher one.
  coincident_lines.py --keeps A.SVG B.SVG   the two drawings hold the same length per layer
"""
import math
import re
import sys
from collections import defaultdict


def layers(path):
    out = defaultdict(list)  # "visible"/"hidden" -> paths (lists of points)
    name = None
    for m in re.finditer(r'inkscape:label="[0-9]+ ([a-z-]+)"|<path d="([^"]*)"', open(path).read()):
        if m.group(1):
            name = m.group(1)
        elif name:
            p = [float(v) for v in re.findall(r"-?[0-9]+(?:\.[0-9]*)?", m.group(2))]
            pts = list(zip(p[0::2], p[1::2]))
            if m.group(2).rstrip().endswith("Z"):
                pts.append(pts[0])
            out[name].append(pts)
    return out


def segments(paths):
    return [(a, b, i) for i, p in enumerate(paths) for a, b in zip(p, p[1:]) if a != b]


class Grid:
    def __init__(self, segs, cell):
        self.cell, self.segs, self.cells = cell, segs, defaultdict(list)
        for k, (a, b, _) in enumerate(segs):
            for key in self.keys(a, b, 0):
                self.cells[key].append(k)

    def keys(self, a, b, pad):
        c = self.cell
        for x in range(math.floor((min(a[0], b[0]) - pad) / c), math.floor((max(a[0], b[0]) + pad) / c) + 1):
            for y in range(math.floor((min(a[1], b[1]) - pad) / c), math.floor((max(a[1], b[1]) + pad) / c) + 1):
                yield (x, y)

    def near(self, a, b, pad):
        seen = set()
        for key in self.keys(a, b, pad):
            for k in self.cells.get(key, ()):
                if k not in seen:
                    seen.add(k)
                    yield self.segs[k]


def dist(p, a, b):
    dx, dy = b[0] - a[0], b[1] - a[1]
    l2 = dx * dx + dy * dy
    t = 0 if l2 == 0 else max(0, min(1, ((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / l2))
    return math.hypot(p[0] - a[0] - t * dx, p[1] - a[1] - t * dy)


def alongside(p, q, a, b, tol):
    """The length of pq within tol of ab, nearly parallel (2 degrees), its points' feet on ab."""
    dx, dy, ex, ey = q[0] - p[0], q[1] - p[1], b[0] - a[0], b[1] - a[1]
    l, e = math.hypot(dx, dy), math.hypot(ex, ey)
    if l == 0 or e == 0 or abs(dx * ey - dy * ex) > 0.0349 * l * e:
        return 0
    n, run = 20, 0
    for k in range(n):
        t = (k + 0.5) / n
        x = (p[0] + t * dx, p[1] + t * dy)
        u = ((x[0] - a[0]) * ex + (x[1] - a[1]) * ey) / (e * e)
        if 0 <= u <= 1 and abs((x[0] - a[0]) * ey - (x[1] - a[1]) * ex) / e <= tol:
            run += 1
    return l * run / n


def merged_checks(merged, exact, tol):
    m, x = layers(merged), layers(exact)
    cls = lambda name: name.split("-")[0]
    vis = [p for n, ps in m.items() if cls(n) == "visible" for p in ps]
    hid = [p for n, ps in m.items() if cls(n) == "hidden" for p in ps]
    vseg, hseg = segments(vis), segments(hid)
    grid = Grid(vseg, 1.0)
    vlen = sum(math.dist(a, b) for a, b, _ in vseg)
    hlen = sum(math.dist(a, b) for a, b, _ in hseg)
    twice = sum(alongside(a, b, c, d, tol) for a, b, i in vseg for c, d, j in grid.near(a, b, tol) if j != i) / 2
    under = sum(alongside(a, b, c, d, tol) for a, b, _ in hseg for c, d, _ in grid.near(a, b, tol))
    print(f"visible {vlen:.1f} mm, drawn twice within {tol} mm: {twice:.2f} mm; hidden {hlen:.1f} mm, under visible: {under:.2f} mm")
    assert twice <= 0.001 * vlen, "visible lines drawn twice"
    assert under <= 0.001 * hlen, "hidden lines under visible ones"
    # Nothing else lost: every sample of the exact drawing is near the merged drawing.
    reach = 0.26
    for c in ("visible", "hidden"):
        allowed = segments(vis) if c == "visible" else segments(vis + hid)
        g = Grid(allowed, 1.0)
        lost = 0
        for n, ps in x.items():
            if cls(n) != c:
                continue
            for a, b, _ in segments(ps):
                for k in range(4):
                    t = (k + 0.5) / 4
                    pt = (a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]))
                    if not any(dist(pt, s, e) <= reach for s, e, _ in g.near(pt, pt, reach)):
                        lost += 1
        print(f"{c}: {lost} samples of the exact drawing farther than {reach} mm from the merged one")
        assert lost == 0, f"{c} lines lost by the merge"
    print("coincident lines ok")


def keeps(a, b):
    la, lb = layers(a), layers(b)
    length = lambda ps: sum(math.dist(p, q) for s in ps for p, q in zip(s, s[1:]))
    for n in sorted(set(la) | set(lb)):
        assert abs(length(la.get(n, [])) - length(lb.get(n, []))) < 1e-6, (n, length(la.get(n, [])), length(lb.get(n, [])))
    print("lines kept", sorted(la))


if __name__ == "__main__":
    if sys.argv[1] == "--keeps":
        keeps(sys.argv[2], sys.argv[3])
    else:
        merged_checks(sys.argv[1], sys.argv[2], float(sys.argv[3]))
