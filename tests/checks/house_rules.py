#!/usr/bin/env python3
"""The house rules of docs/design.md ("The folder map"), checked on the tracked files:
- no folder of algorithms/ or io/ holds more than 20 files, and no source file is over 700 lines;
- the unit roundoff and the 2D orientation filter are defined once (kernel/error_bounds.hpp,
  kernel/predicates_2d.hpp);
- the repository speaks to its users: no words about how the work was organised;
- no build output (CMakeFiles/, CMakeCache.txt) is committed.
Usage: house_rules.py ROOT (exit 1 and one line per broken rule)."""
import os
import re
import subprocess
import sys

def self_test():
    """Each rule must catch its breach: a tiny repository that breaks all of them."""
    import tempfile
    with tempfile.TemporaryDirectory() as t:
        def put(path, text):
            os.makedirs(os.path.dirname(os.path.join(t, path)), exist_ok=True)
            open(os.path.join(t, path), "w").write(text)
        for k in range(21):
            put(f"algorithms/big/f{k}.hpp", "#pragma once\n")
        put("io/long.cpp", "int x;\n" * 701)
        put("algorithms/big/dup.cpp", "constexpr double u = 0x1p-53;\n")
        put("docs/notes.md", "Measured in the third " + "ses" + "sion.\n")
        put("CMakeFiles/CMakeOutput.log", "log\n")
        subprocess.run(["git", "init", "-q", t], check=True)
        subprocess.run(["git", "-C", t, "add", "-A"], check=True)
        r = subprocess.run([sys.executable, __file__, t], capture_output=True, text=True)
        want = ["holds 22 files", "701 lines", "defines again", "how the work was organised", "a build output is committed"]
        missing = [w for w in want if w not in r.stdout]
        if r.returncode != 1 or missing:
            sys.exit("house_rules --self-test: not caught: " + ", ".join(missing) + "\n" + r.stdout)
    print("house_rules --self-test: every rule catches its breach")
    sys.exit(0)


if sys.argv[1:] == ["--self-test"]:
    self_test()
root = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "..", "..")
files = subprocess.run(["git", "ls-files"], cwd=root, capture_output=True, text=True, check=True).stdout.split()
files = [f for f in files if os.path.exists(os.path.join(root, f))]
bad = []

for f in files:
    if f.split("/")[0] == "CMakeFiles" or "/CMakeFiles/" in f or f.endswith("CMakeCache.txt"):
        bad.append(f"{f}: a build output is committed")

folders = {}
for f in files:
    if f.startswith(("algorithms/", "io/")):
        folders.setdefault(os.path.dirname(f), []).append(f)
for d, fs in sorted(folders.items()):
    if d in ("algorithms", "io"):
        bad.append(f"{d}/ holds files of its own ({', '.join(fs)}): each goes into a capability folder")
    elif len(fs) > 20:
        bad.append(f"{d}/ holds {len(fs)} files (at most 20: split the capability)")

sources = [f for f in files if f.endswith((".cpp", ".hpp", ".py", ".sh")) and not f.startswith("tests/golden/")]
for f in sources:
    n = sum(1 for _ in open(os.path.join(root, f), encoding="utf-8", errors="replace"))
    if n > 700:
        bad.append(f"{f}: {n} lines (at most 700)")

library = [f for f in sources if f.startswith(("kernel/", "algorithms/", "io/")) and f.endswith((".cpp", ".hpp"))]
once = {
    r"0x1p-5[23]\b": "kernel/error_bounds.hpp",  # the unit roundoff and a rational's double error
    r"\(b\[0\] - a\[0\]\) \* \(c\[1\] - a\[1\]\)": "kernel/predicates_2d.hpp",  # the orientation determinant in doubles
    r"1e-9 \* std::max": "kernel/error_bounds.hpp",  # the pad of picture boxes
}
for pattern, home in once.items():
    for f in library:
        if f != home and re.search(pattern, open(os.path.join(root, f), encoding="utf-8").read()):
            bad.append(f"{f}: defines again what lives in {home} ({pattern})")

# The words, spelled in pieces so that this file does not hold them itself.
words = re.compile("|".join([r"\bses" + r"sions?\b", r"\biss" + r"ues? [0-9]", r"\bsee" + r"ds? 00[0-9]", "this " + "VM"]), re.I)
for f in files:
    if f.startswith(("tests/golden/", "data/")) or f.endswith((".png", ".pdf", ".svg", ".off", ".stl")):
        continue
    try:
        text = open(os.path.join(root, f), encoding="utf-8").read()
    except UnicodeDecodeError:
        continue
    for k, line in enumerate(text.splitlines(), 1):
        if words.search(line):
            bad.append(f"{f}:{k}: words about how the work was organised: {line.strip()[:100]}")
for b in bad:
    print(b)
print(f"house_rules: {len(bad)} broken" if bad else "house_rules: every rule holds")
sys.exit(1 if bad else 0)
