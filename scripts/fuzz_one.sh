#!/usr/bin/env bash
# Runs one libFuzzer target for SECONDS, seeded with the matching files of DATA (and data/bad),
# keeping its corpus in CORPUS. Crashes are written to CORPUS/../crash-* and fail the run.
# Usage: scripts/fuzz_one.sh FUZZER SECONDS DATA CORPUS
set -euo pipefail
fuzzer="$1"; seconds="$2"; data="$3"; corpus="$4"
name="$(basename "$fuzzer")"
mkdir -p "$corpus"
seeds="$corpus.seeds"
rm -rf "$seeds"; mkdir -p "$seeds"
case "$name" in
  fuzz_off)     exts="off" ;;
  fuzz_obj)     exts="obj" ;;
  fuzz_stl)     exts="stl" ;;
  fuzz_ply)     exts="ply" ;;
  fuzz_scene)   exts="yaml yml json" ;;
  fuzz_problem) exts="yaml" ;;
  fuzz_tile)    exts="tile" ;;
  fuzz_number)  exts="" ; i=0; for s in 0.1 -3/7 1e-3 2.5E+2 nan 1/0 +7 .5 5.; do i=$((i+1)); printf '%s' "$s" > "$seeds/n$i"; done ;;
  fuzz_render|fuzz_horizon) exts="" ; i=0; for s in 0123456789abcdef 'zzzzzzzzzzzzzzzz' 'AAAAAAAAAAAAAAAAAAAAAAAA' '1q2w3e4r5t6y7u8i9o0p'; do i=$((i+1)); printf '%s' "$s" > "$seeds/r$i"; done ;;
  fuzz_options) exts="" ; printf '1,13/10,1.7' > "$seeds/v"; printf 'box:0,2,0,2,0,2' > "$seeds/b"; printf 'frustum:-4,4,-4,4,1,-3,5' > "$seeds/f"; printf -- '-2,-1,1/2,3/2,3/2,-1/2' > "$seeds/s" ;;
esac
for ext in $exts; do
  find "$data" -name "*.$ext" -size -64k -exec cp -t "$seeds" {} + 2>/dev/null || true
done
dict="$(dirname "$0")/../tests/fuzz/${name}.dict"
args=(-max_total_time="$seconds" -max_len=65536 -rss_limit_mb=2048 -timeout=10 -artifact_prefix="$corpus/../crash-$name-" -print_final_stats=1)
[ -f "$dict" ] && args+=(-dict="$dict")
exec "$fuzzer" "${args[@]}" "$corpus" "$seeds"
