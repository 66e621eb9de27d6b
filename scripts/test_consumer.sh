#!/usr/bin/env bash
# Installs the build into a temporary prefix, then builds and runs examples/consumer against
# the installed ExactHLR package, outside the source tree; imports the installed Python package.
#   scripts/test_consumer.sh [BUILD_DIR]
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BUILD="$(realpath "${1:-$ROOT/build}")"
WORK="$(mktemp -d)"
trap 'rm -rf "$WORK"' EXIT
cmake --install "$BUILD" --prefix "$WORK/prefix" >/dev/null
cp -r "$ROOT/examples/consumer" "$WORK/src"
cmake -S "$WORK/src" -B "$WORK/build" -DCMAKE_PREFIX_PATH="$WORK/prefix" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$WORK/build" -j "$(nproc 2>/dev/null || echo 2)" >/dev/null
"$WORK/build/render_cube"
# The installed hlr reads models through the installed model module (LIBDIR/exact-hlr).
step=/usr/share/opencascade/data/step/screw.step
if [ -e "$step" ]; then
  LD_DEBUG=files "$WORK/prefix/bin/hlr" render "$step" --view iso -o "$WORK/screw.svg" 2> "$WORK/loaded.txt"
  grep -q "file=$WORK/prefix/.*/exact-hlr/libhlr_models.so" "$WORK/loaded.txt" || { echo "consumer: the installed hlr did not load the installed model module" >&2; exit 1; }
  echo "consumer: installed model module read $step"
fi
# The Python package that cmake --install put under the prefix (HLR_PYTHON_INSTALL_DIR).
site="$(sed -n 's/^HLR_PYTHON_INSTALL_DIR:PATH=//p' "$BUILD/CMakeCache.txt")"
if [ -n "$site" ]; then
  case "$site" in /*) ;; *) site="$WORK/prefix/$site" ;; esac
  (cd "$WORK" && PYTHONPATH="$site" /usr/bin/python3 -c "
import exact_hlr
assert exact_hlr.__file__.startswith('$site'), exact_hlr.__file__
d = exact_hlr.render(([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], [[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]]), view='iso')
assert len(d) == 6 and d.svg().startswith('<?xml')
print('consumer: python package', exact_hlr.__version__, 'installed')")
fi
