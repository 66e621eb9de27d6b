#!/usr/bin/env bash
# Sets up, builds and runs the whole test suite; ends with ctest's summary.
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$ROOT/scripts/setup.sh"
"$ROOT/scripts/extract_corpus.sh" >/dev/null
cd "${HLR_BUILD_DIR:-$ROOT/build}"
ctest --output-on-failure -j "$(nproc 2>/dev/null || echo 2)"
