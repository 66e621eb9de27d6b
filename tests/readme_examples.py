#!/usr/bin/env python3
"""Runs every example of README.md and docs/*.md as written (what the README shows is tested).

  readme_examples.py ROOT BUILD_DIR MESH_DIR [--list]

In a fresh folder that holds `build` (the build under test), the repository's files (links to
them: `data`, `examples`, `pyproject.toml`, ...) and the meshes the README names (MESH_DIR: the CGAL meshes that
scripts/extract_corpus.sh extracts):

- every command of a ```sh block runs with bash (continuation lines joined) and must exit 0.
  Not run: the README's two commands (scripts/demo.sh and scripts/test.sh: this test is part of
  the second) and job scripts for other machines (a block that starts with #!, such as a Slurm
  job array);
- every `$ COMMAND` line of another block is a transcript: the command runs, and what it prints
  (standard output and error) must be the lines shown under it; it must exit 0, or non-zero
  when the first line shown is an error (`hlr: ...` or `hlr COMMAND: ...`);
- every ```python block of `>>>` lines runs as a doctest (PYTHONPATH=build/python): each
  value shown must be the value printed.

Prints one line per example and a summary; exits 1 when any example fails.
"""
import doctest
import glob
import os
import re
import subprocess
import sys
import tempfile

SKIPPED = {"scripts/demo.sh", "scripts/test.sh"}


def examples(path):
    text = open(path, encoding="utf-8").read()
    for m in re.finditer(r"^```(\w*)\n(.*?)^```", text, re.S | re.M):
        lang, body = m.group(1), m.group(2)
        line = text[: m.start()].count("\n") + 2
        if lang in ("sh", "bash"):
            if body.startswith("#!"):
                continue
            command = ""
            for k, raw in enumerate(body.splitlines()):
                command += raw
                if raw.endswith("\\"):
                    command = command[:-1] + " "
                    continue
                cmd = command.strip()
                command = ""
                if not cmd or cmd.startswith("#") or cmd.split()[0] in SKIPPED:
                    continue
                yield ("sh", f"{path}:{line + k}", cmd, None)
        elif lang == "python" and ">>>" in body:
            yield ("python", f"{path}:{line}", body, None)
        elif lang == "":
            lines = body.splitlines()
            for k, raw in enumerate(lines):
                if not raw.startswith("$ "):
                    continue
                shown = []
                for nxt in lines[k + 1:]:
                    if nxt.startswith("$ "):
                        break
                    shown.append(nxt)
                while shown and not shown[-1].strip():
                    shown.pop()
                yield ("transcript", f"{path}:{line + k}", raw[2:], shown)


def run_sh(cmd, work, env):
    p = subprocess.run(["bash", "-c", cmd], cwd=work, env=env, capture_output=True, text=True, timeout=600)
    if p.returncode != 0:
        return f"exit {p.returncode}: {(p.stderr or p.stdout).strip()[-400:]}"
    return None


def run_transcript(cmd, shown, work, env):
    p = subprocess.run(["bash", "-c", "exec 2>&1\n" + cmd], cwd=work, env=env, capture_output=True, text=True, timeout=600)
    got = p.stdout.rstrip("\n").splitlines() if p.stdout.strip() else []
    want_error = bool(shown) and re.match(r"^hlr( [a-z]+)?: ", shown[0]) is not None
    if (p.returncode != 0) != want_error:
        return f"exit {p.returncode} ({'an error' if want_error else 'success'} shown)"
    if got != shown:
        diff = next((i for i in range(max(len(got), len(shown))) if i >= len(got) or i >= len(shown) or got[i] != shown[i]), 0)
        return f"prints other lines than shown, from line {diff + 1}: {got[diff:diff + 1]} vs {shown[diff:diff + 1]}"
    return None


def run_python(body, work, env):
    old = os.getcwd()
    os.chdir(work)
    sys.path.insert(0, os.path.join(work, "build", "python"))
    try:
        test = doctest.DocTestParser().get_doctest(body, {}, "README", "README.md", 0)
        runner = doctest.DocTestRunner(optionflags=doctest.NORMALIZE_WHITESPACE)
        out = []
        runner.run(test, out=out.append)
        return None if runner.failures == 0 else "".join(out)[-800:]
    finally:
        sys.path.pop(0)
        os.chdir(old)


def main(argv):
    root, build, meshes = (os.path.realpath(a) for a in argv[1:4])
    found = [e for f in ["README.md"] + sorted(glob.glob(os.path.join(root, "docs", "*.md"))) for e in examples(os.path.join(root, f))]
    if "--list" in argv:
        for kind, where, cmd, _ in found:
            print(f"{kind} {os.path.relpath(where, root)}: {cmd.splitlines()[0]}")
        return 0
    failed = 0
    with tempfile.TemporaryDirectory() as work:
        os.symlink(build, os.path.join(work, "build"))
        for d in sorted(os.listdir(root)):  # the source tree (`pip install .`), as a clone has it
            if not d.startswith(("build", ".")):
                os.symlink(os.path.join(root, d), os.path.join(work, d))
        for m in glob.glob(os.path.join(meshes, "*.off")):
            os.symlink(m, os.path.join(work, os.path.basename(m)))
        # Debian's python3 first (as on a machine the README's commands set up)
        env = dict(os.environ, PYTHONPATH=os.path.join(work, "build", "python"), PATH="/usr/bin:" + os.environ.get("PATH", ""))
        for kind, where, cmd, shown in found:
            where = os.path.relpath(where, root)
            if kind == "sh":
                why = run_sh(cmd, work, env)
            elif kind == "transcript":
                why = run_transcript(cmd, shown, work, env)
            else:
                why = run_python(cmd, work, env)
            first = cmd.splitlines()[0] if kind != "python" else "python doctest"
            if why:
                failed += 1
                print(f"FAILED {where}: {first}\n  {why}")
            else:
                print(f"ok {where}: {first[:100]}")
    print(f"readme examples: {len(found) - failed} of {len(found)} ran as written")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
