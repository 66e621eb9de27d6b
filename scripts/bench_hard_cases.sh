#!/usr/bin/env bash
# The hard cases (extreme shapes), whole `hlr render` runs to SVG (wall time, GNU time): a prism on
# a 10,000-gon (target under 1 s) and on a 32,768-gon (65,536 vertices), a non-convex 4,004-gon
# star prism, 10,000 cubes with the eye inside the cloud against the orthographic view (target
# within 3x; faces on one mesh, Roberts on 10,000 box bodies), a 200k-triangle torus with the
# eye in its hole against the outside view (target within 3x). Writes build/bench/hard_cases.md.
#   scripts/bench_hard_cases.sh
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BUILD="${HLR_BUILD_DIR:-$ROOT/build}"
HLR="$BUILD/hlr"
GEN="$BUILD/benchmarks/gen_mesh"
OUT="$BUILD/bench"
[ -x "$HLR" ] && [ -x "$GEN" ] || { echo "bench_hard_cases: build first (scripts/setup.sh)" >&2; exit 1; }
mkdir -p "$OUT/meshes"
gen() { local f="$OUT/meshes/$1"; [ -s "$f" ] || "$GEN" "${@:2}" > "$f"; echo "$f"; }
run() {  # label, args...
  local label="$1"
  shift
  /usr/bin/time -f "%e %M" "$HLR" render "$@" -o "$OUT/hard.svg" 2> "$OUT/hard.log" > /dev/null
  local t
  t=$(tail -1 "$OUT/hard.log")
  echo "| $label | $(echo "$t" | awk '{print $1}') | $(echo "$t" | awk '{printf "%.0f", $2/1024}') |" >> "$report"
  echo "$label: $t"
}
report="$OUT/hard_cases.md"
{
  echo "# hlr render: the hard cases ($(date -u +%Y-%m-%d), $(nproc) cores)"
  echo
  echo "| case | wall s | peak MB |"
  echo "|---|---|---|"
} > "$report"
prism=$(gen prism10k.off prism 10000)
run "prism on a 10,000-gon, view 1,1.3,1.7" "$prism" --view 1,1.3,1.7
run "prism on a 32,768-gon (65,536 vertices)" "$(gen prism32k.off prism 32768)" --view 1,1.3,1.7
run "non-convex 4,004-gon star prism" "$(gen star2002.off star 2002)" --view 1,1.3,1.7
cubes=$(gen cubes10k.off cubes 10000)
run "10,000 cubes (one mesh), orthographic" "$cubes" --view 1,1.3,1.7
run "10,000 cubes (one mesh), eye inside the cloud" "$cubes" --eye 32.6,32.6,32.6 --target 0,0,0
scene=$(gen cubes10k.yaml cube-scene 10000)
run "10,000 box bodies, Roberts, orthographic" "$scene" --method roberts --view 1,1.3,1.7
run "10,000 box bodies, Roberts, eye inside the cloud" "$scene" --method roberts --eye 32.6,32.6,32.6 --target 0,0,0
torus=$(gen torus200k.off torus 316 316)
run "torus 200k triangles, --edges all, outside view" "$torus" --view 1,1.3,1.7 --edges all
run "torus 200k triangles, --edges all, eye in the hole" "$torus" --eye 0,0,0 --target 1,0,0 --edges all
# Touching unit cubes on a grid (every other one: (x + 2y + 3z) mod 2), seen along an axis: the
# 2D clean-up meets thousands of collinear pieces that touch end to end.
touching="$OUT/meshes/touching-cubes.off"
[ -s "$touching" ] || awk 'BEGIN {
  nv = 0; nf = 0
  for (x = 0; x < 18; x++) for (y = 0; y < 18; y++) for (z = 0; z < 18; z++) if ((x + 2 * y + 3 * z) % 2 == 0) {
    for (k = 0; k < 8; k++) v[nv + k] = (x + (k == 1 || k == 2 || k == 5 || k == 6)) " " (y + (k == 2 || k == 3 || k == 6 || k == 7)) " " (z + (k >= 4))
    f[nf++] = nv " " nv + 3 " " nv + 2 " " nv + 1; f[nf++] = nv + 4 " " nv + 5 " " nv + 6 " " nv + 7
    f[nf++] = nv " " nv + 1 " " nv + 5 " " nv + 4; f[nf++] = nv + 2 " " nv + 3 " " nv + 7 " " nv + 6
    f[nf++] = nv + 1 " " nv + 2 " " nv + 6 " " nv + 5; f[nf++] = nv " " nv + 4 " " nv + 7 " " nv + 3
    nv += 8
  }
  print "OFF"; print nv, nf, 0
  for (i = 0; i < nv; i++) print v[i]
  for (i = 0; i < nf; i++) print 4, f[i]
}' > "$touching"
run "2,916 touching cubes, front view, hidden dashed (2D clean-up)" "$touching" --view front --hidden dashed
echo "wrote $report"
