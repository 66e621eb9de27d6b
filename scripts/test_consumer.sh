#!/usr/bin/env bash
# Installs the build into a temporary prefix, then builds and runs examples/consumer against
# the installed ExactHLR package, outside the source tree.
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
