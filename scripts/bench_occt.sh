#!/usr/bin/env bash
# Open CASCADE's hidden lines against exact-hlr on Open CASCADE's own file: the 100k-triangle
# sphere written as Open CASCADE writes numbers (`%.10g` with its 1e-17 noise,
# benchmarks/exporter_formats.py), every edge with its visibility along 1,1.3,1.7.
# HLRBRep_PolyAlgo (benchmarks/polyalgo_peer.cpp: the mesh as one face per triangle, as Open
# CASCADE reads STL) against `hlr render --edges all`, in alternating runs, best of 3 each. The
# peer's time is its hidden-line computation and extraction alone (not reading and building the
# shape); ours the whole process to SVG. Writes build/bench/occt.md.
# Usage: scripts/bench_occt.sh [RUNS]   (default 3)
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BUILD="${HLR_BUILD_DIR:-$ROOT/build}"
OUT="$BUILD/bench"
RUNS="${1:-3}"
[ -x "$BUILD/hlr" ] && [ -x "$BUILD/benchmarks/gen_mesh" ] || { echo "bench_occt: build first (scripts/setup.sh)" >&2; exit 1; }
command -v /usr/bin/time >/dev/null || { echo "bench_occt: needs GNU time (apt install time)" >&2; exit 1; }
cmake --build "$BUILD" --target polyalgo_peer >/dev/null
d="$OUT/numbers/sphere100k"
if [ ! -s "$d/occt.off" ]; then
  mkdir -p "$d"
  "$BUILD/benchmarks/gen_mesh" sphere 71 > "$d/source.off"
  python3 "$ROOT/benchmarks/exporter_formats.py" "$d/source.off" "$d"
fi
best_peer="" best_build="" best_hlr="" peer_line=""
for _ in $(seq "$RUNS"); do
  line="$("$BUILD/benchmarks/polyalgo_peer" "$d/occt.off" 1 1.3 1.7)"
  t="$(awk '{for (i = 1; i < NF; ++i) if ($i == "hlr") print $(i + 1)}' <<<"$line")"
  b="$(awk '{for (i = 1; i < NF; ++i) if ($i == "build") print $(i + 1)}' <<<"$line")"
  if [ -z "$best_peer" ] || awk "BEGIN{exit !($t < $best_peer)}"; then best_peer=$t; best_build=$b; peer_line=$line; fi
  /usr/bin/time -f "%e %M" -o "$OUT/time.txt" "$BUILD/hlr" render "$d/occt.off" --edges all --view 1,1.3,1.7 -o "$OUT/occt.svg"
  read -r w kb <"$OUT/time.txt"
  if [ -z "$best_hlr" ] || awk "BEGIN{exit !($w < $best_hlr)}"; then best_hlr=$w; mem=$((kb / 1024)); fi
done
report="$OUT/occt.md"
{
  echo "# Open CASCADE HLRBRep_PolyAlgo against exact-hlr ($(date -u +%Y-%m-%d), $(nproc) cores, $(awk '/MemTotal/{printf "%d GiB", $2/1048576}' /proc/meminfo))"
  echo
  echo "The 100k-triangle sphere in Open CASCADE's \`%.10g\` with noise, every edge along 1,1.3,1.7, best of $RUNS in alternating runs."
  echo
  echo "| program | time |"
  echo "|---|---|"
  echo "| exact-hlr, whole process to SVG | $best_hlr s, $mem MB |"
  echo "| HLRBRep_PolyAlgo, hidden lines and extraction | $best_peer s (building the shape and meshing it: $best_build s more) |"
  echo
  echo "exact-hlr is $(awk "BEGIN{printf \"%.0f\", $best_peer / $best_hlr}")x faster. The peer: $peer_line"
} >"$report"
cat "$report"
