#!/usr/bin/env bash
# Remakes data/openscad/*.off from Debian's OpenSCAD examples (package openscad, not needed by
# the build or the tests: the small OFF files are checked in). example002 is a cone cut by a
# cube's faces, whose intersection curves fall under the crease angle near their tangent
# points.
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
EXAMPLES=/usr/share/openscad/examples/Old
command -v openscad >/dev/null || { echo "openscad_examples: install Debian's openscad" >&2; exit 1; }
for n in 001 002 004; do
  openscad -o "$ROOT/data/openscad/example$n.off" "$EXAMPLES/example$n.scad"
done
