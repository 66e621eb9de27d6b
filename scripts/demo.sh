#!/usr/bin/env bash
# Sets up, builds and runs hlr on the bundled demo scene; prints where the output is.
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$ROOT/scripts/setup.sh"
BUILD_DIR="${HLR_BUILD_DIR:-$ROOT/build}"
OUT="$BUILD_DIR/demo"
mkdir -p "$OUT"
"$BUILD_DIR/hlr" info --matrix "$ROOT/data/demo.yaml" | tee "$OUT/info.txt"
echo
echo "demo: output written to $OUT/info.txt"
