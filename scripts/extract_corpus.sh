#!/usr/bin/env bash
# Extracts the OFF meshes of Debian's libcgal-demo (data.tar.gz) into build/corpus/meshes.
# Prints the folder. Large meshes are never committed; tests and benchmarks read them from here.
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
DEST="${HLR_CORPUS_DIR:-$ROOT/build/corpus}"  # the tests read <build dir>/corpus/meshes
ARCHIVE=/usr/share/doc/libcgal-dev/data.tar.gz
[ -f "$ARCHIVE" ] || ARCHIVE=/usr/share/doc/libcgal-demo/data.tar.gz
if [ ! -f "$DEST/.done" ]; then
  mkdir -p "$DEST"
  tar xzf "$ARCHIVE" -C "$DEST" --strip-components=1 --wildcards 'data/meshes/*.off'
  touch "$DEST/.done"
fi
echo "$DEST/meshes"
