#!/usr/bin/env bash
# Tiles: `hlr render --tile I/N` on every tile, then `hlr merge`, gives the untiled
# drawing byte for byte (SVG with hidden lines; JSON with only the visibility's work counters
# blanked: those are the tiles' sums) on 1, 4 and 9 tiles, for the demo scene (orthographic
# and perspective with the eye among the bodies), a sphere with every edge, a grid of cubes
# seen along an axis (edges lying on the tile lines, which pass through vertices), 400 random
# interpenetrating triangles (intersection lines, open surfaces), a transparent scene (lines
# seen through) and triangles with coordinates far outside doubles (orthographic, and with
# the eye among them). Then the merge's errors: a missing tile, a tile given twice, tiles of another
# render, a file cut short, not a tile file: a message and exit code 1 or 2, no output.
# Usage: tests/tile_identity.sh HLR GEN_MESH DATA_DIR
set -euo pipefail
hlr="$(realpath "$1")"; gen="$2"; data="$(realpath "$3")"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
"$gen" sphere 20 > "$work/sphere.off"
"$gen" cubes 4 > "$work/cubes.off"
"$gen" triangles 400 7 > "$work/tris.off"
# 60 random triangles with coordinates of 300 digits and of 10^-400 (beyond doubles: the
# filters work in the drawing frame, the decisions stay exact).
python3 - "$work" <<'PY'
import random, sys
random.seed(5)
for name, suffix in [("huge", "0" * 300), ("tiny", "/1" + "0" * 400)]:
    lines = ["OFF", "180 60 0"]
    for i in range(180):
        lines.append(" ".join("%d%s" % (random.randint(-50, 50), suffix) for _ in range(3)))
    lines += ["3 %d %d %d" % (3 * f, 3 * f + 1, 3 * f + 2) for f in range(60)]
    open(sys.argv[1] + "/" + name + ".off", "w").write("\n".join(lines) + "\n")
PY
cd "$work"
fail=0
blank() { sed -E 's/"(pairs_tested|pairs_skipped_by_prefilter|pairs_on_rational_path|parameter_comparisons[a-z_]*)":[0-9]+/"\1":"_"/g' "$1"; }
check() {  # name, then render's arguments
  local name="$1"; shift
  "$hlr" render "$@" -o whole.svg 2>/dev/null
  "$hlr" render "$@" -o whole.json 2>/dev/null
  for n in 1 4 9; do
    rm -f part*.tile
    for i in $(seq 1 "$n"); do
      "$hlr" render "$@" --tile "$i/$n" -o "part$i.tile" 2> err || { echo "$name: tile $i/$n failed: $(cat err)"; fail=1; return; }
    done
    # Any order of the files.
    "$hlr" merge $(ls part*.tile | sort -r) -o merged.svg 2> err || { echo "$name: merge of $n failed: $(cat err)"; fail=1; return; }
    "$hlr" merge part*.tile -o merged.json 2> err || { echo "$name: merge of $n (JSON) failed: $(cat err)"; fail=1; return; }
    cmp -s whole.svg merged.svg || { echo "$name: $n tiles: merged SVG differs"; fail=1; }
    cmp -s <(blank whole.json) <(blank merged.json) || { echo "$name: $n tiles: merged JSON differs"; fail=1; }
  done
  echo "$name: identical on 1, 4 and 9 tiles"
}
check demo "$data/demo.yaml" --hidden dashed
check demo-perspective "$data/demo.yaml" --eye 9,-7,6 --hidden dashed
check demo-eye-among "$data/demo.yaml" --eye 5,0.5,1.3 --target 2,2,0.5 --hidden dashed
check sphere-all-edges sphere.off --view 1,1.3,1.7 --edges all --hidden dashed
check cubes-axis cubes.off --view 0,0,1 --hidden solid
check cubes-diagonal cubes.off --view 1,1,0 --hidden dashed
check triangles tris.off --view 1,1.3,1.7 --hidden dashed
check transparent "$data/transparency_demo.yaml" --hidden dashed
check digits-300 huge.off --view 1,1.3,1.7 --hidden dashed
check digits-minus-400 tiny.off --view 1,1.3,1.7 --hidden dashed
check eye-among-huge huge.off --eye 0,0,0 --target 1,1,1 --hidden dashed
# The page formats from the same tiles: PDF, PNG and DXF byte for byte too.
rm -f part*.tile
for i in 1 2 3 4; do "$hlr" render "$data/demo.yaml" --hidden dashed --page A4 --tile "$i/4" -o "part$i.tile" 2>/dev/null; done
for f in pdf png dxf; do
  "$hlr" render "$data/demo.yaml" --hidden dashed --page A4 -o "whole.$f" 2>/dev/null
  "$hlr" merge part*.tile -o "merged.$f" 2>/dev/null
  cmp -s "whole.$f" "merged.$f" || { echo "demo $f: merged differs"; fail=1; }
done
echo "demo: PDF, PNG and DXF identical from 4 tiles"
# Errors: each a message naming the problem, a non-zero exit, no output file.
rm -f part*.tile merged.svg
for i in 1 2 3 4; do "$hlr" render "$data/demo.yaml" --tile "$i/4" -o "part$i.tile" 2>/dev/null; done
"$hlr" render "$data/demo.yaml" --view 1,2,3 --tile 4/4 -o other.tile 2>/dev/null
head -5 part1.tile > short.tile
echo "hello" > bad.tile
expect_error() {  # what, expected message part, merge arguments
  local what="$1" msg="$2"; shift 2
  if "$hlr" merge "$@" -o merged.svg 2> err; then echo "$what: merge succeeded"; fail=1; return; fi
  grep -q "$msg" err || { echo "$what: message '$(cat err)' lacks '$msg'"; fail=1; }
  [ ! -e merged.svg ] || { echo "$what: wrote output"; fail=1; }
  echo "$what: refused ($(head -1 err))"
}
expect_error "missing tile" "tile 3 of 4 is missing" part1.tile part2.tile part4.tile
expect_error "tile twice" "is also" part1.tile part2.tile part2.tile part3.tile part4.tile
expect_error "another render" "other input or options" part1.tile part2.tile part3.tile other.tile
expect_error "cut short" "without 'end'" part1.tile part2.tile part3.tile short.tile
expect_error "not a tile" "not an hlr tile file" part1.tile part2.tile part3.tile bad.tile
"$hlr" render "$data/demo.yaml" --tile 5/4 -o x.tile 2> err && { echo "--tile 5/4 accepted"; fail=1; }
grep -q "is not I/N" err || { echo "--tile 5/4: message '$(cat err)'"; fail=1; }
[ "$fail" = 0 ] && echo "tile identity: all identical"
