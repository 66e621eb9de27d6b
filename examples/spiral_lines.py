#!/usr/bin/env python3
"""A spiral wound around the unit sphere (data/sphere2000.off), as hlr render --lines reads it:
one polyline, x y z per point, from pole to pole, 3% above the surface.
  examples/spiral_lines.py [TURNS] [POINTS] > spiral.txt"""
import math
import sys

turns = float(sys.argv[1]) if len(sys.argv) > 1 else 14
points = int(sys.argv[2]) if len(sys.argv) > 2 else 1400
r = 1.03
out = []
for k in range(points + 1):
    s = k / points
    phi = math.pi * (0.02 + 0.96 * s)  # from near one pole to near the other
    theta = 2 * math.pi * turns * s
    out.append("%.6f %.6f %.6f" % (r * math.sin(phi) * math.cos(theta), r * math.cos(phi), r * math.sin(phi) * math.sin(theta)))
print("# a spiral around the unit sphere: %g turns, %d points" % (turns, points))
print(" ".join(out))
