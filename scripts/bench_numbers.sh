#!/usr/bin/env bash
# Number formats: the same mesh written the ways exporters write numbers
# (benchmarks/exporter_formats.py: %.7f, Open CASCADE's %.10g with 1e-17 noise, %g, %.7g,
# %.17g, numpy's %.18e, float32 binary STL), each drawn with `--edges all --view 1,1.3,1.7`
# by every hlr given (e.g. a build before and after a change) in alternating runs, best of 3
# (HLR_BENCH_ROUNDS: more, where this machine's neighbours make single runs noisy)
# wall seconds (GNU time) with peak memory, and the cost against the same mesh in short fixed
# decimals. The SVGs of the builds are compared byte for byte (exactness is not traded). Meshes:
# the 100k-triangle icosphere and bunny00; with --large also the 1M icosphere. Writes
# build/bench/numbers.md.
# Usage: scripts/bench_numbers.sh [--large] [HLR ...]   (default: build/hlr)
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BUILD="${HLR_BUILD_DIR:-$ROOT/build}"
OUT="$BUILD/bench"
LARGE=0
ROUNDS="${HLR_BENCH_ROUNDS:-3}"
if [ "${1:-}" = "--large" ]; then LARGE=1; shift; fi
[ $# -gt 0 ] || set -- "$BUILD/hlr"
for h in "$@"; do [ -x "$h" ] || { echo "bench_numbers: $h is not a program" >&2; exit 1; }; done
GEN="$BUILD/benchmarks/gen_mesh"
[ -x "$GEN" ] || { echo "bench_numbers: build first (scripts/setup.sh)" >&2; exit 1; }
command -v /usr/bin/time >/dev/null || { echo "bench_numbers: needs GNU time (apt install time)" >&2; exit 1; }
MESHES="$(cd "$("$ROOT/scripts/extract_corpus.sh")" && pwd)"
mkdir -p "$OUT/numbers"
sources=()
mk() {  # name generator-args...
  local d="$OUT/numbers/$1"
  if [ ! -s "$d/float32.stl" ]; then
    mkdir -p "$d"
    if [ "$2" = copy ]; then cp "$3" "$d/source.off"; else "$GEN" "${@:2}" > "$d/source.off"; fi
    python3 "$ROOT/benchmarks/exporter_formats.py" "$d/source.off" "$d"
  fi
  sources+=("$1")
}
mk sphere100k sphere 71
mk bunny00 copy "$MESHES/bunny00.off"
[ "$LARGE" = 1 ] && mk sphere1m sphere 224
formats=(fixed7.off occt.off g.off g7.off repr.off numpy.off float32.stl)
report="$OUT/numbers.md"
fail=0
{
  echo "# Number formats ($(date -u +%Y-%m-%d), $(nproc) cores, $(awk '/MemTotal/{printf "%d GiB", $2/1048576}' /proc/meminfo))"
  echo
  echo "\`--edges all --view 1,1.3,1.7\` to SVG, whole process, best of $ROUNDS in alternating runs: wall s, peak MB, and the"
  echo "ratio to the same build on the fixed-decimal file."
  echo
  header="| mesh | format |"
  rule="|---|---|"
  for h in "$@"; do header="$header $h |"; rule="$rule---|"; done
  echo "$header"
  echo "$rule"
  for m in "${sources[@]}"; do
    declare -A base=()
    for f in "${formats[@]}"; do
      declare -A best=() mem=()
      for _ in $(seq "$ROUNDS"); do
        i=0
        for h in "$@"; do
          /usr/bin/time -f "%e %M" -o "$OUT/time.txt" "$h" render "$OUT/numbers/$m/$f" --edges all --view 1,1.3,1.7 \
            -o "$OUT/numbers/out$i.svg" >/dev/null 2>&1
          read -r w kb <"$OUT/time.txt"
          if [ -z "${best[$h]:-}" ] || awk "BEGIN{exit !($w < ${best[$h]})}"; then best[$h]=$w; fi
          mem[$h]=$((kb / 1024))
          i=$((i + 1))
        done
      done
      for ((k = 1; k < i; ++k)); do
        if ! cmp -s "$OUT/numbers/out0.svg" "$OUT/numbers/out$k.svg"; then
          echo "bench_numbers: $m/$f: the builds' drawings differ" >&2
          fail=1
        fi
      done
      row="| $m | ${f%.*} |"
      for h in "$@"; do
        [ "$f" = fixed7.off ] && base[$h]=${best[$h]}
        row="$row ${best[$h]} s, ${mem[$h]} MB, $(awk "BEGIN{printf \"%.2fx\", ${best[$h]} / ${base[$h]}}") |"
      done
      echo "$row"
      unset best mem
    done
    unset base
  done
} | tee "$report"
echo "bench_numbers: $report" >&2
exit "$fail"
