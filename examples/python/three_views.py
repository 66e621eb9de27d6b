#!/usr/bin/env python3
"""Three views of a mesh loaded with numpy, on one PDF sheet, with exact hidden lines.

    python3 examples/python/three_views.py data/l_prism.off l_prism.pdf

Reads the OFF file with numpy (any (vertices, faces) arrays will do: trimesh's, an STL you
parsed, a generated grid), renders the front, top and right views and an isometric one on an A4
sheet, and prints what the numpy arrays of the iso view say.
"""
import sys

import numpy as np

import exact_hlr


def read_off(path):
    words = " ".join(line.split("#")[0] for line in open(path)).split()
    assert words[0] == "OFF"
    nv, nf = int(words[1]), int(words[2])
    numbers = words[4:]
    vertices = np.array(numbers[: 3 * nv], dtype=np.float64).reshape(nv, 3)
    faces, at = [], 3 * nv
    for _ in range(nf):
        n = int(numbers[at])
        faces.append([int(x) for x in numbers[at + 1: at + 1 + n]])
        at += 1 + n
    return vertices, faces


def main(mesh, pdf):
    vertices, faces = read_off(mesh)
    sheet = exact_hlr.render((vertices, faces), views="front,top,right,iso", page="A4", landscape=True, hidden="dashed")
    sheet.save(pdf)
    iso = sheet.views["iso"]
    a = iso.arrays()
    length = np.linalg.norm(a["end"] - a["start"], axis=1)
    print(f"{pdf}: {len(iso)} pieces in the iso view, {int(a['visible'].sum())} visible, "
          f"visible length {length[a['visible']].sum():.3f}, hidden {length[~a['visible']].sum():.3f} (picture units)")


if __name__ == "__main__":
    main(*(sys.argv[1:3] if len(sys.argv) > 2 else ("data/l_prism.off", "l_prism.pdf")))
