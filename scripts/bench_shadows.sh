#!/usr/bin/env bash
# Shadows benchmark: `hlr render --shadows` against `--surfaces` on CGAL's fandisk,
# couplingdown and bunny00 under the default light, view 1,1.3,1.7, and the shadows demo scene
# (a directional and a point light). Per run: wall time and peak memory (GNU time), the
# surfaces step and the shadows step with its views from the lights (--timings), and the faces
# that needed no arrangement (lit wholly or not at all). Writes build/bench/shadows.md.
# Usage: scripts/bench_shadows.sh
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BUILD="${HLR_BUILD_DIR:-$ROOT/build}"
HLR="$BUILD/hlr"
OUT="$BUILD/bench"
[ -x "$HLR" ] || { echo "bench_shadows: build first (scripts/setup.sh)" >&2; exit 1; }
command -v /usr/bin/time >/dev/null || { echo "bench_shadows: needs GNU time (apt install time)" >&2; exit 1; }
MESHES="$("$ROOT/scripts/extract_corpus.sh")"
mkdir -p "$OUT"
inputs=("$ROOT/data/shadows_demo.yaml" "$MESHES/fandisk.off" "$MESHES/couplingdown.off" "$MESHES/bunny00.off")
run() {  # prints "wall_s peak_MB" and leaves --timings in $OUT/t.err
  local view=(--view 1,1.3,1.7)
  case "$1" in *.yaml) view=() ;; esac
  /usr/bin/time -f "%e %M" -o "$OUT/time.txt" "$HLR" render "$@" "${view[@]}" --timings -o "$OUT/out.svg" 2> "$OUT/t.err" >/dev/null
  read -r wall kb < "$OUT/time.txt"
  echo "$wall $((kb / 1024))"
}
report="$OUT/shadows.md"
{
  echo "# hlr render --shadows benchmark ($(date -u +%Y-%m-%d), $(nproc) cores)"
  echo
  echo "| scene | faces | --surfaces: wall s, peak MB | --shadows: wall s, peak MB | surfaces step s | shadows step s (views from the lights) | faces without arrangement |"
  echo "|---|---|---|---|---|---|---|"
  for m in "${inputs[@]}"; do
    name="$(basename "${m%.*}")"
    read -r sw sm < <(run "$m" --surfaces)
    faces="$(sed -n 's/timings: faces \([0-9]*\),.*/\1/p' "$OUT/t.err")"
    read -r hw hm < <(run "$m" --shadows)
    sstep="$(sed -n 's/timings: surfaces \([0-9.]*\) s.*/\1/p' "$OUT/t.err")"
    line="$(grep 'timings: shadows' "$OUT/t.err")"
    hstep="$(echo "$line" | sed -n 's/timings: shadows \([0-9.]*\) s (views from the lights \([0-9.]*\) s).*/\1 (\2)/p')"
    whole="$(echo "$line" | sed -n 's/.*faces \([0-9]*\) (\([0-9]*\) lit wholly.*/\2 of \1/p')"
    echo "| $name | $faces | $sw, $sm | $hw, $hm | $sstep | $hstep | $whole |"
  done
} > "$report"
cat "$report"
