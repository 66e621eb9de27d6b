#!/usr/bin/env python3
"""Writes one mesh the ways real exporters write numbers (docs/performance.md, "Number formats").

    exporter_formats.py MESH.off OUTDIR

The mesh is first turned by 90 degrees about z in doubles, as a CAD kernel's transform does:
a coordinate that should be 0 becomes noise such as 6.123233995736766e-17 (cos(pi/2)). The
turned doubles are then written as:
  fixed7.off     %.7f   short fixed decimals (the benchmark generator's own form)
  occt.off       %.10g  ten significant digits, noise kept (Open CASCADE's mesh writers)
  g.off          %g     six significant digits (Blender-style and many small writers)
  g7.off         %.7g   float precision in text (MeshLab's float meshes)
  repr.off       %.17g  every double written back exactly (Python's repr, trimesh)
  numpy.off      %.18e  numpy.savetxt's default
  float32.stl    binary STL, float32 corners (OpenSCAD, slicers, most CAD "export STL")
Faces are written as triangles (fanned) so that every file holds the same triangles.
"""
import math
import os
import struct
import sys


def read_off(path):
    with open(path) as f:
        words = f.read().split()
    assert words[0] == "OFF", "not an OFF file"
    nv, nf = int(words[1]), int(words[2])
    at = 4
    verts = []
    for _ in range(nv):
        verts.append(tuple(float(w) for w in words[at:at + 3]))
        at += 3
    faces = []
    for _ in range(nf):
        n = int(words[at])
        idx = [int(w) for w in words[at + 1:at + 1 + n]]
        at += 1 + n
        for k in range(1, n - 1):
            faces.append((idx[0], idx[k], idx[k + 1]))
    return verts, faces


def turned(verts):
    c, s = math.cos(math.pi / 2), math.sin(math.pi / 2)
    return [(x * c - y * s, x * s + y * c, z) for x, y, z in verts]


def write_off(path, verts, faces, fmt):
    with open(path, "w") as f:
        f.write("OFF\n%d %d 0\n" % (len(verts), len(faces)))
        for v in verts:
            f.write(" ".join(fmt % x for x in v) + "\n")
        for t in faces:
            f.write("3 %d %d %d\n" % t)


def write_stl32(path, verts, faces):
    with open(path, "wb") as f:
        f.write(b"exporter_formats float32".ljust(80, b" "))
        f.write(struct.pack("<I", len(faces)))
        for t in faces:
            f.write(struct.pack("<3f", 0.0, 0.0, 0.0))
            for i in t:
                f.write(struct.pack("<3f", *verts[i]))
            f.write(b"\0\0")


FORMATS = [("fixed7", "%.7f"), ("occt", "%.10g"), ("g", "%g"), ("g7", "%.7g"), ("repr", "%.17g"),
           ("numpy", "%.18e")]


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    verts, faces = read_off(sys.argv[1])
    verts = turned(verts)
    os.makedirs(sys.argv[2], exist_ok=True)
    for name, fmt in FORMATS:
        write_off(os.path.join(sys.argv[2], name + ".off"), verts, faces, fmt)
    write_stl32(os.path.join(sys.argv[2], "float32.stl"), verts, faces)


if __name__ == "__main__":
    main()
