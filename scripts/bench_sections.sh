#!/usr/bin/env bash
# Sections benchmark: `hlr render` plain against the same view with a section (--section, a
# plane through the middle) and a half section (--cutaway, two planes), and the house's floor
# plan against its top view; whole process, best of 5 in alternating runs of every hlr given
# (e.g. a build before and after a change), wall seconds (to the millisecond) and peak memory
# (GNU time), the
# section's cost against the same build's plain view. The builds' SVGs are compared byte for
# byte. Models: the house scene, CGAL's fandisk and couplingdown, and with --large a
# 1M-triangle sphere (gen_mesh sphere 224). Writes build/bench/sections.md.
# Usage: scripts/bench_sections.sh [--large] [HLR ...]   (default: build/hlr)
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BUILD="${HLR_BUILD_DIR:-$ROOT/build}"
OUT="$BUILD/bench"
LARGE=0
if [ "${1:-}" = "--large" ]; then LARGE=1; shift; fi
[ $# -gt 0 ] || set -- "$BUILD/hlr"
for h in "$@"; do [ -x "$h" ] || { echo "bench_sections: $h is not a program" >&2; exit 1; }; done
command -v /usr/bin/time >/dev/null || { echo "bench_sections: needs GNU time (apt install time)" >&2; exit 1; }
MESHES="$("$ROOT/scripts/extract_corpus.sh")"
mkdir -p "$OUT/sections"
inputs=("$ROOT/data/house.yaml" "$MESHES/fandisk.off" "$MESHES/couplingdown.off")
if [ "$LARGE" = 1 ]; then
  [ -s "$OUT/sphere1m.off" ] || "$BUILD/benchmarks/gen_mesh" sphere 224 > "$OUT/sphere1m.off"
  inputs+=("$OUT/sphere1m.off")
fi
fail=0
# Best of 5 of every build on one job, in alternating runs: "wall_s peak_MB" per build, one
# line each; the SVGs compared.
runs() {
  declare -A best=() mem=()
  for _ in 1 2 3 4 5; do
    local i=0
    for h in "${builds[@]}"; do
      local t0 t1
      t0=$(date +%s%N)
      /usr/bin/time -f "%M" -o "$OUT/time.txt" "$h" render "$@" -o "$OUT/sections/out$i.svg" >/dev/null 2>&1
      t1=$(date +%s%N)
      read -r kb <"$OUT/time.txt"
      w=$(awk "BEGIN{printf \"%.3f\", ($t1 - $t0) / 1e9}")
      if [ -z "${best[$i]:-}" ] || awk "BEGIN{exit !($w < ${best[$i]})}"; then best[$i]=$w; fi
      mem[$i]=$((kb / 1024))
      i=$((i + 1))
    done
  done
  for ((i = 1; i < ${#builds[@]}; i++)); do
    cmp -s "$OUT/sections/out0.svg" "$OUT/sections/out$i.svg" || { echo "bench_sections: $* draws differently in ${builds[$i]}" >&2; fail=1; }
  done
  for ((i = 0; i < ${#builds[@]}; i++)); do echo "${best[$i]} ${mem[$i]}"; done
}
builds=("$@")
report="$OUT/sections.md"
{
  echo "# hlr render with sections ($(date -u +%Y-%m-%d), $(nproc) cores, $(awk '/MemTotal/{printf "%d GiB", $2/1048576}' /proc/meminfo))"
  echo
  echo "Whole process, best of 5 in alternating runs: wall s, peak MB; the ratio to the same build's plain view."
  echo
  header="| model | job |"
  rule="|---|---|"
  for h in "$@"; do header="$header $h |"; rule="$rule---|"; done
  echo "$header"
  echo "$rule"
  for m in "${inputs[@]}"; do
    name="$(basename "${m%.*}")"
    view=(--view 1,1.3,1.7)
    case "$m" in
      *house.yaml) view=(); mid="y>4.5"; ax="x>4"; ay="y>3" ;;
      *) mid="z<0.0001"; ax="x>0.0001"; ay="y>0.0001" ;;
    esac
    mapfile -t plain < <(runs "$m" "${view[@]}")
    mapfile -t section < <(runs "$m" "${view[@]}" --section "$mid")
    mapfile -t cutaway < <(runs "$m" "${view[@]}" --cutaway "$ax" --cutaway "$ay")
    for job in plain section cutaway; do
      declare -n rows="$job"
      line="| $name | $job |"
      for ((i = 0; i < ${#builds[@]}; i++)); do
        read -r w mb <<<"${rows[$i]}"
        read -r pw _ <<<"${plain[$i]}"
        if [ "$job" = plain ]; then line="$line $w s, $mb MB |"; else line="$line $w s, $mb MB ($(awk "BEGIN{printf \"%.2f\", $w/$pw}")x) |"; fi
      done
      echo "$line"
    done
  done
  mapfile -t top < <(runs "$ROOT/data/house.yaml" --view top)
  mapfile -t plan < <(runs "$ROOT/data/house.yaml" --plan 1.2)
  line="| house | --plan 1.2 |"
  for ((i = 0; i < ${#builds[@]}; i++)); do
    read -r w mb <<<"${plan[$i]}"
    read -r pw _ <<<"${top[$i]}"
    line="$line $w s, $mb MB ($(awk "BEGIN{printf \"%.2f\", $w/$pw}")x the top view) |"
  done
  echo "$line"
} > "$report"
cat "$report"
exit "$fail"
