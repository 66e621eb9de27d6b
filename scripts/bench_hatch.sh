#!/usr/bin/env bash
# Tone hatching benchmark: whole `hlr render` runs to SVG, `--surfaces` (fills) against
# `--hatch` (5 tone levels, the same visible polygons hatched by shade), best of 3 each, on
# CGAL's fandisk, couplingdown and bunny00, view 1,1.3,1.7; wall time and peak memory (GNU
# time), the hatch's strokes (--stats). Writes build/bench/hatch.md.
# Usage: scripts/bench_hatch.sh
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BUILD="${HLR_BUILD_DIR:-$ROOT/build}"
HLR="$BUILD/hlr"
OUT="$BUILD/bench"
[ -x "$HLR" ] || { echo "bench_hatch: build first (scripts/setup.sh)" >&2; exit 1; }
command -v /usr/bin/time >/dev/null || { echo "bench_hatch: needs GNU time (apt install time)" >&2; exit 1; }
MESHES="$(HLR_CORPUS_DIR="$BUILD/corpus" "$ROOT/scripts/extract_corpus.sh")"
mkdir -p "$OUT"
best() {  # best of 3: prints "wall_s peak_MB"
  local best_w="" best_m=""
  for _ in 1 2 3; do
    /usr/bin/time -f "%e %M" -o "$OUT/time.txt" "$HLR" render "$@" --view 1,1.3,1.7 --stats -o "$OUT/out.svg" 2> "$OUT/h.err" >/dev/null
    read -r w kb < "$OUT/time.txt"
    if [ -z "$best_w" ] || awk "BEGIN{exit !($w < $best_w)}"; then best_w=$w best_m=$((kb / 1024)); fi
  done
  echo "$best_w $best_m"
}
report="$OUT/hatch.md"
{
  echo "# hlr render --hatch benchmark ($(date -u +%Y-%m-%d), $(nproc) cores, $(free -g | awk '/Mem:/{print $2}') GiB)"
  echo
  echo "| mesh | faces | --surfaces: wall s, peak MB | --hatch: wall s, peak MB | ratio | hatch strokes |"
  echo "|---|---|---|---|---|---|"
  for name in fandisk couplingdown bunny00; do
    m="$MESHES/$name.off"
    faces="$(awk 'NR==2{print $2; exit}' "$m")"
    read -r sw sm < <(best "$m" --surfaces)
    read -r hw hm < <(best "$m" --hatch)
    strokes="$(grep -h 'tone-' "$OUT/h.err" | awk '{s += $(NF-4)} END {print s}')"
    echo "| $name | $faces | $sw, $sm | $hw, $hm | $(awk "BEGIN{printf \"%.2f\", $hw / $sw}") | $strokes |"
  done
} > "$report"
cat "$report"
