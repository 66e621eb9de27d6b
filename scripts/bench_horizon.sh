#!/usr/bin/env bash
# Speed of `hlr horizon`: whole process to SVG for expression grids from 61 x 241 to
# 1,000 x 1,000 and the bundled heightmap, with peak memory. Usage: scripts/bench_horizon.sh
# [BUILD_DIR] (default build). Writes BUILD/bench/horizon.md.
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD="${1:-build}"
HLR="$BUILD/hlr"
[ -x "$HLR" ] || { echo "bench_horizon: build first (scripts/setup.sh)" >&2; exit 1; }
mkdir -p "$BUILD/bench"
E="0.35*exp(-6*x^2)*(1+sin(9*z+2*x))^2/4 + 0.02*cos(17*x+7*z)"
run() {  # label, then hlr horizon's arguments
  local label="$1"; shift
  local log
  log=$( { /usr/bin/time -f "TIME %e %M" "$HLR" horizon "$@" -o "$BUILD/bench/horizon.svg"; } 2>&1 )
  echo "| $label | $(echo "$log" | awk '/^TIME/{printf "%s s | %d MB", $2, $3/1024}') |"
}
{
  echo "| grid | whole process to SVG | peak memory |"
  echo "|---|---|---|"
  run "61 cuts x 241 samples" --expr "$E" --x -1:1:241 --z -1:1:61
  run "101 x 301" --expr "$E" --x -1:1:301 --z -1:1:101
  run "heightmap data/terrain.pgm (48 x 120)" --grid data/terrain.pgm --x -1.5:1.5 --z -0.6:0.6 --height 0.45 --angles 35,0
  run "300 x 300" --expr "$E" --x -1:1:300 --z -1:1:300
  [ "${QUICK:-0}" = 1 ] || run "1,000 x 1,000" --expr "$E" --x -1:1:1000 --z -1:1:1000
} | tee "$BUILD/bench/horizon.md"
