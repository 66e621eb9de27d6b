#!/usr/bin/env bash
# Sets up, builds and renders the bundled demo scene (several convex bodies, one pair
# interpenetrating) to an SVG with hidden lines dashed, its exact JSON, and a print-ready A4
# sheet of four views (PDF, hidden lines cut into dashes); prints the paths.
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
HLR_BUILD_TARGET=hlr "$ROOT/scripts/setup.sh"   # the program alone: the test command builds the rest
BUILD_DIR="${HLR_BUILD_DIR:-$ROOT/build}"
OUT="$BUILD_DIR/demo"
mkdir -p "$OUT"
"$BUILD_DIR/hlr" info "$ROOT/data/demo.yaml" > "$OUT/info.txt"
"$BUILD_DIR/hlr" render "$ROOT/data/demo.yaml" --hidden dashed -o "$OUT/demo.svg"
"$BUILD_DIR/hlr" render "$ROOT/data/demo.yaml" -o "$OUT/demo.json"
"$BUILD_DIR/hlr" render "$ROOT/data/demo.yaml" --views front,top,right,iso --page A4 --landscape --hidden dashed \
  --dashes geometry --quiet -o "$OUT/sheet.pdf"
echo "demo: drawing     $OUT/demo.svg"
echo "demo: exact JSON  $OUT/demo.json"
echo "demo: A4 sheet    $OUT/sheet.pdf"
echo "demo: body report $OUT/info.txt"
