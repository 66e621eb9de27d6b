#!/usr/bin/env bash
# The Python package as its users install it, tested there and not in the build tree:
#   1. `python3 -m build --wheel` makes the wheel (the in-tree backend, python/build_backend,
#      reusing BUILD_DIR), pip installs it into a fresh virtual environment (Debian's numpy
#      and pytest through --system-site-packages; no package index), and the pytest suite runs
#      against it from a folder outside the tree, with the environment's `hlr`;
#   2. `pip install .` from the tree installs it into a second environment, where the
#      one-liner of the README runs.
#   tests/python_package.sh BUILD_DIR
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BUILD="$(realpath "$1")"
WORK="$(mktemp -d)"
trap 'rm -rf "$WORK"' EXIT
PY=/usr/bin/python3

"$PY" -m venv --system-site-packages "$WORK/venv"
"$PY" -m build --wheel -C build-dir="$BUILD" --outdir "$WORK/dist" "$ROOT" >"$WORK/build.log" 2>&1 || { cat "$WORK/build.log"; exit 1; }
wheel="$(ls "$WORK"/dist/*.whl)"
echo "python package: built $(basename "$wheel")"
"$WORK/venv/bin/pip" install --no-index --quiet "$wheel"
cd "$WORK"
HLR_BIN="$WORK/venv/bin/hlr" HLR_EXPECT_INSTALLED=1 HLR_DATA_DIR="$ROOT/data" \
  "$WORK/venv/bin/python" -m pytest -q -p no:cacheprovider "$ROOT/python/tests"

"$PY" -m venv --system-site-packages "$WORK/venv2"
(cd "$ROOT" && "$WORK/venv2/bin/pip" install --no-index --quiet --config-settings build-dir="$BUILD" .)
"$WORK/venv2/bin/python" -c "import exact_hlr; exact_hlr.render(([[0,0,0],[1,0,0],[0,1,0],[0,0,1]], [[0,2,1],[0,1,3],[0,3,2],[1,2,3]]), view='iso').svg()"
# Models are read by the model module the wheel holds beside _core: from Python, and from the
# environment's hlr program.
step=/usr/share/opencascade/data/step/screw.step
if [ -e "$step" ]; then
  LD_DEBUG=files "$WORK/venv/bin/python" -c "import exact_hlr; assert len(exact_hlr.render('$step', view='iso')) > 0" 2> "$WORK/py_loaded.txt"
  LD_DEBUG=files "$WORK/venv/bin/hlr" render "$step" --view iso -o "$WORK/screw.svg" 2> "$WORK/hlr_loaded.txt"
  for f in py_loaded hlr_loaded; do
    grep -q "file=$WORK/venv/lib/python3[^ ]*/site-packages/exact_hlr/libhlr_models.so" "$WORK/$f.txt" \
      || { echo "python package: $f: the wheel's model module was not the one loaded" >&2; exit 1; }
  done
  echo "python package: the wheel's model module reads STEP"
fi
"$WORK/venv2/bin/python" -c "import exact_hlr, sys; assert exact_hlr.__file__.startswith(sys.prefix); print('python package: pip install . OK,', exact_hlr.__version__)"
