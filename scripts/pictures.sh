#!/usr/bin/env bash
# Regenerates every published picture (docs/*.svg, docs/*.png) with the command that makes it,
# and compares each with the committed file (tests/picture_compare.py: an SVG's fills with their
# colours, strokes and layers must be the same, and the pixels of both pictures, as rsvg-convert
# draws an SVG, may differ in at most 0.5% of their 4 x 4 blocks). A writer or a pipeline that
# stops drawing a product fails here. The test command runs it; --update writes the pictures
# into docs/ (look at them before committing).
#   scripts/pictures.sh [--update] [BUILD_DIR]
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
update=0
if [ "${1:-}" = "--update" ]; then update=1; shift; fi
BUILD="$(realpath "${1:-$ROOT/build}")"
HLR="$BUILD/hlr"
MESHES="$(HLR_CORPUS_DIR="$BUILD/corpus" "$ROOT/scripts/extract_corpus.sh")"
W="$(mktemp -d)"
trap 'rm -rf "$W"' EXIT
ln -s "$ROOT/data" "$W/data"
ln -s "$MESHES/fandisk.off" "$W/fandisk.off"
ln -s "$MESHES/couplingdown.off" "$W/couplingdown.off"
cd "$W"
fail=0 count=0
picture() {  # NAME COMMAND ARGS...: the picture docs/NAME is `hlr COMMAND ARGS... -o NAME`
  local name="$1"
  shift
  count=$((count + 1))
  "$HLR" "$@" -o "$W/$name" 2>/dev/null || { echo "$name: hlr $* failed"; fail=1; return; }
  if [ "$update" = 1 ]; then
    cp "$W/$name" "$ROOT/docs/$name"
    echo "$name: written"
  elif [ ! -f "$ROOT/docs/$name" ]; then
    echo "$name: not committed"; fail=1
  else
    python3 "$ROOT/tests/picture_compare.py" same "$W/$name" "$ROOT/docs/$name" || fail=1
  fi
}
picture demo.svg render data/demo.yaml --hidden dashed --width 160
picture fandisk.svg render fandisk.off --view 1,1.3,1.7 --hidden dashed --width 120
picture fandisk_sheet.svg render fandisk.off --views front,top,right,iso --page A3 --landscape --scale 80:1 --hidden dashed --dashes geometry
picture fandisk_sheet.png render fandisk.off --views front,top,right,iso --page A3 --landscape --scale 80:1 --hidden dashed --dashes geometry --dpi 85
picture demo_surfaces.svg render data/demo_lit.yaml --surfaces
picture fandisk_surfaces.svg render fandisk.off --surfaces --view 1,1.3,1.7
picture shadows_demo.svg render data/shadows_demo.yaml --shadows
picture transparency_demo.svg render data/transparency_demo.yaml --surfaces
picture transparency_lines.svg render data/transparency_demo.yaml
picture three_sticks_priority.svg render data/three_sticks.yaml --method priority
picture raster_demo.png raster data/demo.yaml --algorithm scanline --shading phong --samples 3 --size 640x400
picture sphere_flat.png raster data/sphere2000.off --view 1,1.3,1.7 --shading flat --samples 2 --size 240x240
picture sphere_gouraud.png raster data/sphere2000.off --view 1,1.3,1.7 --shading gouraud --samples 2 --size 240x240
picture sphere_phong.png raster data/sphere2000.off --view 1,1.3,1.7 --shading phong --samples 2 --size 240x240
picture texture_demo.png raster data/texture_demo.yaml --shading phong --samples 3 --size 480x360
picture glass_demo.png raster data/glass_demo.yaml --bounces 6 --samples 3 --size 640x400
picture house_plan.svg render data/house.yaml --plan 1.2 --width 120
picture house_section.svg render data/house.yaml --section 'y>4.5' --width 160
picture couplingdown_half_section.svg render couplingdown.off --view iso --cutaway 'x>0' --cutaway 'y>0' --width 110
python3 "$ROOT/examples/spiral_lines.py" > "$W/spiral.txt"
picture fandisk_hatched.png render fandisk.off --view 1,1.3,1.7 --hatch --width 120 --dpi 200
picture shadows_hatched.png render data/shadows_demo.yaml --shadows --hatch --hatch-levels 6 --dpi 200
picture sphere_spiral.svg render data/sphere2000.off --lines spiral.txt --view 1,1.3,1.7 --hidden dashed --width 100
picture couplingdown_section_sheet.svg render couplingdown.off --views front,section:A,iso --section-view 'A=x<0' --width 150
picture linkrods_sheet.png render /usr/share/opencascade/data/step/linkrods.step --views front,top,right,iso --page A3 --landscape --dpi 85
picture bearing_iso.svg render /usr/share/opencascade/data/iges/bearing.iges --view iso --width 120
picture interior_lines.svg render data/interior_room.yaml --width 120
picture interior_lit_lines.svg render data/interior_lit.yaml --width 120
picture interior_lit.svg render data/interior_lit.yaml --surfaces --shadows --width 120
picture engine_iso.svg render /usr/share/assimp/models/glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb --view iso --width 120
ridge=(horizon --expr "0.35*exp(-6*x^2)*(1+sin(9*z+2*x))^2/4 + 0.02*cos(17*x+7*z)" --x -1.5:1.5:241 --z -1:1:61 --angles 25,0 --stroke 0.25 --width 180)
picture horizon_ridgelines.svg "${ridge[@]}"
picture horizon_ridgelines.png "${ridge[@]}" --page A4 --landscape --dpi 94
picture horizon_terrain.svg horizon --grid data/terrain.pgm --x -1.5:1.5 --z -0.6:0.6 --height 0.45 --angles 35,0 --stroke 0.25 --width 180
committed=$(cd "$ROOT/docs" && ls *.svg *.png | wc -l)
if [ "$committed" != "$count" ]; then
  echo "docs/ holds $committed pictures, this script makes $count: every published picture needs its command here"; fail=1
fi
if [ "$fail" = 0 ]; then echo "pictures: all $count regenerated and the same"; fi
exit "$fail"
