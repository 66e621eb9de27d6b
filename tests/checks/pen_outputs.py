#!/usr/bin/env python3
"""Checks of the files hlr writes for pen plotters (tests/CMakeLists.txt runs them):

  pen_outputs.py lines JSON          polylines through, in front of and behind the cube: the
                                     exact visible and hidden pieces
  pen_outputs.py dxf DXF TEXT...     the DXF's $INSUNITS is 4 (millimetres) and its TEXT
                                     entities hold every TEXT given
  pen_outputs.py stats SVG STATS MM  --stats's "the file holds N strokes" is the SVG's <path>
                                     count, and no path is shorter than MM (--min-length)
"""
import json
import math
import re
import sys
from fractions import Fraction as F


def lines(path):
    segs = [s for s in json.load(open(path))["segments"] if s.get("kind") == "polyline"]
    got = {}
    for s in segs:
        a, b = [tuple(F(v) for v in s[k]) for k in ("from", "to")]
        key = "x" if a[1] == b[1] else ("front" if a[2] == 2 else "behind")
        lo, hi = (a, b) if a < b else (b, a)
        got.setdefault(key, []).append((lo[0 if key == "x" else 1], hi[0 if key == "x" else 1], s["visible"]))
    got = {k: sorted(v) for k, v in got.items()}
    # The cube [-1,1]^3 seen from +z: through it along x, inside hidden; in front all seen; behind
    # it hidden where the cube covers it.
    want = {"x": [(-3, -1, True), (-1, 1, False), (1, 3, True)], "front": [(-3, 3, True)],
            "behind": [(-3, -1, True), (-1, 1, False), (1, 3, True)]}
    assert got == want, got
    print("polyline pieces ok")


def stats(svg, text, min_mm):
    t = open(svg).read()
    paths = re.findall(r'<path d="([^"]*)"', t)
    held = int(re.search(r"the file holds ([0-9]+) strokes", open(text).read()).group(1))
    assert held == len(paths), (held, len(paths))
    short = 0
    for d in paths:
        p = [float(v) for v in re.findall(r"-?[0-9]+(?:\.[0-9]*)?", d)]
        q = list(zip(p[0::2], p[1::2]))
        short += sum(math.dist(a, b) for a, b in zip(q, q[1:])) < float(min_mm) - 1e-3
    assert short == 0, f"{short} paths shorter than {min_mm} mm"
    print("stats hold", held)


def dxf(path, *want):
    t = [line.rstrip("\r") for line in open(path, encoding="latin-1").read().split("\n")]
    pairs = list(zip(t[0::2], t[1::2]))  # (group code, value)
    units = [v for (c, v), (c2, v2) in zip(pairs, pairs[1:]) if v == "$INSUNITS" for v in [v2.strip()]]
    assert units == ["4"], units
    texts, entity = [], None
    for c, v in pairs:
        if c.strip() == "0":
            entity = v.strip()
        elif entity == "TEXT" and c.strip() == "1":
            texts.append(v)
    missing = [w for w in want if w not in texts]
    assert not missing, (missing, texts)
    print("dxf units and texts", texts)


if __name__ == "__main__":
    {"lines": lines, "stats": stats, "dxf": dxf}[sys.argv[1]](*sys.argv[2:])
