#!/usr/bin/env bash
# The torture suite's long mode: thousands of random scenes. Lines: the eye among the bodies, on
# face planes and on surfaces, axis views; every piece of both routes checked by exact ray
# casting and the routes compared. Every other product (tests/io/product_torture_test.cpp): visible
# surfaces, transparency, shadows, the priority list, the four raster algorithms and the floating
# horizon, each sampled and checked by exact ray casting, with repaired meshes' face numbers.
# Runs until SECONDS (default 1800) have passed, 1000 scenes per seed; prints each seed's tally
# and stops at the first failure.
#   scripts/torture.sh [SECONDS]
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BUILD="${HLR_BUILD_DIR:-$ROOT/build}"
LIMIT="${1:-1800}"
[ -x "$BUILD/tests/hlr_tests" ] || { echo "torture: build first (scripts/setup.sh)" >&2; exit 1; }
start=$(date +%s)
seed=1000
total=0
while [ $(( $(date +%s) - start )) -lt "$LIMIT" ]; do
  out=$(HLR_TORTURE_SCENES=1000 HLR_TORTURE_SEED=$seed "$BUILD/tests/hlr_tests" --gtest_filter='Torture.*:ProductTorture.*' 2>&1) || {
    echo "$out" | grep -E "^faces|^roberts|^seed|scene|Failure" | head -20 || true
    echo "torture: FAILED at seed $seed (HLR_TORTURE_DUMP=1 prints the scene)"
    exit 1
  }
  echo "$out" | grep '\[torture\]' | sed "s/^/seed $seed: /" || true
  total=$((total + 1000))
  seed=$((seed + 1))
done
echo "torture: $total scenes, no wrong piece"
