#!/usr/bin/env python3
"""The folder map of docs/design.md, checked: every #include "..." of the project's own headers
must go to the file's own folder or to a folder the map lets it include, and no public header
(.hpp) outside the two bridges includes CGAL, OpenMesh, Eigen or oneTBB.

Usage: include_map.py ROOT   (exit 1 and one line per offending include)."""
import os
import re
import sys

def self_test():
    """The check must fail on an include against the map: a support header that includes the
    pipeline, in a copy of the map."""
    import shutil, subprocess, tempfile
    here = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
    with tempfile.TemporaryDirectory() as t:
        os.makedirs(os.path.join(t, "docs"))
        shutil.copy(os.path.join(here, "docs", "design.md"), os.path.join(t, "docs"))
        for d in ("algorithms/support", "io/pipeline"):
            os.makedirs(os.path.join(t, d))
        open(os.path.join(t, "io/pipeline/render.hpp"), "w").write("#pragma once\n")
        open(os.path.join(t, "algorithms/support/bad.hpp"), "w").write('#include "io/pipeline/render.hpp"\n#include <CGAL/Gmpq.h>\n')
        r = subprocess.run([sys.executable, __file__, t], capture_output=True, text=True)
        want = ["algorithms/support may not include io/pipeline", "a public header includes <CGAL/Gmpq.h>"]
        if r.returncode != 1 or not all(w in r.stdout for w in want):
            sys.exit("include_map --self-test: the check did not catch a bad include:\n" + r.stdout)
    print("include_map --self-test: a bad include and a heavy header are caught")
    sys.exit(0)

if sys.argv[1:] == ["--self-test"]:
    self_test()
root = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "..", "..")
design = open(os.path.join(root, "docs", "design.md"), encoding="utf-8").read()
block = re.search(r"```include-map\n(.*?)```", design, re.S)
if not block:
    sys.exit("include_map: docs/design.md has no ```include-map block")
allowed = {}
for line in block.group(1).splitlines():
    line = line.split("#", 1)[0].strip()
    if not line:
        continue
    folder, _, rest = line.partition(":")
    allowed[folder.strip()] = rest.split()

def folder_of(path):
    """The map's name for the folder holding `path` (the longest folder the map names)."""
    parts = path.split("/")
    for n in range(len(parts) - 1, 0, -1):
        f = "/".join(parts[:n])
        if f in allowed:
            return f
    return None

def may_include(src, dst):
    if src == dst:
        return True
    for a in allowed[src]:
        # "io" allows every io/* folder; "algorithms/picture" only that one.
        if dst == a or dst.startswith(a + "/"):
            return True
    return False

tops = set(f.split("/")[0] for f in allowed)
bridges = {"kernel/epeck_bridge.hpp", "kernel/openmesh_mesh.hpp"}
heavy = re.compile(r"#include\s*<(CGAL|OpenMesh|Eigen|tbb|oneapi)/")
own = re.compile(r'#include\s*"([^"]+)"')
bad = []
for top in sorted(tops):
    for dirpath, _, files in os.walk(os.path.join(root, top)):
        for name in sorted(files):
            if not name.endswith((".cpp", ".hpp")):
                continue
            rel = os.path.relpath(os.path.join(dirpath, name), root).replace(os.sep, "/")
            src = folder_of(rel)
            if src is None:
                bad.append(f"{rel}: its folder is not in the map of docs/design.md")
                continue
            text = open(os.path.join(root, rel), encoding="utf-8").read()
            for k, line in enumerate(text.splitlines(), 1):
                m = own.match(line.strip())
                if m and m.group(1).split("/")[0] in tops:
                    dst = folder_of(m.group(1))
                    if dst is None or not os.path.exists(os.path.join(root, m.group(1))):
                        bad.append(f"{rel}:{k}: includes {m.group(1)}, which is not a file of a mapped folder")
                    elif not may_include(src, dst):
                        bad.append(f"{rel}:{k}: {src} may not include {dst} ({m.group(1)}); see the map in docs/design.md")
                if rel.endswith(".hpp") and rel not in bridges and heavy.match(line.strip()):
                    bad.append(f"{rel}:{k}: a public header includes {line.strip()[9:]} (keep it in .cpp files)")
for b in bad:
    print(b)
print(f"include_map: {len(bad)} includes against the map" if bad else "include_map: every include follows the map")
sys.exit(1 if bad else 0)
