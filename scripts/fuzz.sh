#!/usr/bin/env bash
# Builds the libFuzzer targets (clang, ASan + UBSan) and runs each for SECONDS (default 60),
# one after another, keeping corpora in build-asan/fuzz-corpus/. Prints each target's executions
# and whether it found a crash (saved as build-asan/fuzz-corpus/crash-*; turn each into a file
# in data/bad/ and a test).
#   scripts/fuzz.sh [SECONDS] [TARGET...]
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
SECONDS_EACH="${1:-60}"
shift || true
CC=clang CXX=clang++ HLR_BUILD_DIR="$ROOT/build-asan" HLR_BUILD_TYPE=RelWithDebInfo \
  "$ROOT/scripts/setup.sh" -DHLR_SANITIZE=ON -DHLR_FUZZ=ON -DHLR_BUILD_BENCHMARKS=OFF
targets=("$@")
[ ${#targets[@]} -gt 0 ] || targets=(fuzz_number fuzz_off fuzz_obj fuzz_stl fuzz_ply fuzz_scene fuzz_problem fuzz_options fuzz_render fuzz_horizon fuzz_tile)
out="$ROOT/build-asan/fuzz-corpus"
mkdir -p "$out"
status=0
for t in "${targets[@]}"; do
  log="$out/$t.log"
  if "$ROOT/scripts/fuzz_one.sh" "$ROOT/build-asan/tests/fuzz/$t" "$SECONDS_EACH" "$ROOT/data" "$out/corpus-$t" >"$log" 2>&1; then
    result="ok"
  else
    result="CRASH (see $log)"
    status=1
  fi
  runs="$(grep -o 'stat::number_of_executed_units: [0-9]*' "$log" | awk '{print $2}' | tail -1)"
  printf '%-14s %12s executions in %ss: %s\n' "$t" "${runs:-?}" "$SECONDS_EACH" "$result"
done
exit $status
