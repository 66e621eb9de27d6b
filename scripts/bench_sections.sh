#!/usr/bin/env bash
# Sections benchmark: `hlr render` plain against the same view with a section (--section, a
# plane through the middle), a half section (--cutaway, two planes) and the house's floor plan,
# whole process, best of 3 each, with peak memory (GNU time). Models: the house scene, CGAL's
# fandisk and couplingdown, and with --large a 1M-triangle sphere (gen_mesh sphere 224).
# Writes build/bench/sections.md.
# Usage: scripts/bench_sections.sh [--large]
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BUILD="${HLR_BUILD_DIR:-$ROOT/build}"
HLR="$BUILD/hlr"
OUT="$BUILD/bench"
[ -x "$HLR" ] || { echo "bench_sections: build first (scripts/setup.sh)" >&2; exit 1; }
command -v /usr/bin/time >/dev/null || { echo "bench_sections: needs GNU time (apt install time)" >&2; exit 1; }
MESHES="$("$ROOT/scripts/extract_corpus.sh")"
mkdir -p "$OUT"
inputs=("$ROOT/data/house.yaml" "$MESHES/fandisk.off" "$MESHES/couplingdown.off")
if [ "${1:-}" = "--large" ]; then
  "$BUILD/benchmarks/gen_mesh" sphere 224 > "$OUT/sphere1m.off"
  inputs+=("$OUT/sphere1m.off")
fi
best() {  # best of 3: "wall_s peak_MB"
  local b="" m=0
  for _ in 1 2 3; do
    /usr/bin/time -f "%e %M" -o "$OUT/time.txt" "$HLR" render "$@" -o "$OUT/out.svg" 2>/dev/null >/dev/null
    read -r wall kb < "$OUT/time.txt"
    if [ -z "$b" ] || awk "BEGIN{exit !($wall < $b)}"; then b=$wall; fi
    m=$((kb / 1024))
  done
  echo "$b $m"
}
report="$OUT/sections.md"
{
  echo "# hlr render with sections ($(date -u +%Y-%m-%d), $(nproc) cores, $(awk '/MemTotal/{printf "%d GiB", $2/1048576}' /proc/meminfo))"
  echo
  echo "| model | plain: s, MB | --section (middle): s, MB, ratio | --cutaway (quarter): s, MB, ratio |"
  echo "|---|---|---|---|"
  for m in "${inputs[@]}"; do
    name="$(basename "${m%.*}")"
    view=(--view 1,1.3,1.7)
    case "$m" in
      *house.yaml) view=(); mid="y>4.5"; ax="x>4"; ay="y>3" ;;
      *) mid="z<0.0001"; ax="x>0.0001"; ay="y>0.0001" ;;
    esac
    read -r pw pm < <(best "$m" "${view[@]}")
    read -r sw sm < <(best "$m" "${view[@]}" --section "$mid")
    read -r cw cm < <(best "$m" "${view[@]}" --cutaway "$ax" --cutaway "$ay")
    echo "| $name | $pw, $pm | $sw, $sm, $(awk "BEGIN{printf \"%.1f\", $sw/$pw}") | $cw, $cm, $(awk "BEGIN{printf \"%.1f\", $cw/$pw}") |"
  done
  read -r pw pm < <(best "$ROOT/data/house.yaml" --view top)
  read -r lw lm < <(best "$ROOT/data/house.yaml" --plan 1.2)
  echo
  echo "House floor plan (--plan 1.2) $lw s against $pw s for the plain top view."
} > "$report"
cat "$report"
