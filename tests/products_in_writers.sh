#!/usr/bin/env bash
# Every filled product in every picture writer: visible surfaces, shadows, transparency and the
# priority list, each written as JSON, SVG, PDF and PNG. The SVG must hold one fill per region
# the JSON lists (per shadow region, per transparency region, per painted polygon) in the
# JSON's colours; the PDF (as poppler draws it) and the PNG must look like the SVG (as
# rsvg-convert draws it) and be coloured where it is. A writer that stops drawing a product,
# or a pipeline that stops handing it to the writers, fails here.
#   tests/products_in_writers.sh HLR DATA_DIR
set -euo pipefail
HLR="$(realpath "$1")" D="$(realpath "$2")"
HERE="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
W="$(mktemp -d)"
trap 'rm -rf "$W"' EXIT
fail=0
check() {  # name, how to count the JSON's regions (a Python expression of j), render args...
  local name="$1" count="$2"
  shift 2
  "$HLR" render "$@" -o "$W/$name.json" 2>/dev/null
  "$HLR" render "$@" -o "$W/$name.svg" 2>/dev/null
  "$HLR" render "$@" -o "$W/$name.pdf" 2>/dev/null
  "$HLR" render "$@" --dpi 96 -o "$W/$name.png" 2>/dev/null
  local want got
  want=$(python3 -c "import json,sys; j=json.load(open(sys.argv[1])); print($count)" "$W/$name.json")
  got=$(python3 "$HERE/picture_compare.py" count "$W/$name.svg" | sed -E 's/^fills ([0-9]+).*/\1/')
  if [ "$want" = "any" ]; then
    [ "$got" -gt 0 ] || { echo "$name: the SVG has no fills"; fail=1; }
  elif [ "$got" != "$want" ]; then
    echo "$name: the SVG has $got fills, the JSON $want regions"; fail=1
  fi
  if [ "$want" != "any" ]; then  # the same colours as the JSON's shades
    python3 - "$W/$name.json" "$W/$name.svg" "$count" <<'PY' || fail=1
import json, re, sys
j = json.load(open(sys.argv[1]))
svg = open(sys.argv[2]).read()
fills = sorted(re.findall(r'<path d="[^"]*" fill="(#[0-9a-f]{6})"', svg))
shades = []
if "shadows" in j:
    shades = [r["shade"] for f in j["shadows"]["faces"] for r in f["regions"]]
elif "transparency" in j:
    shades = [r["colour"] for r in j["transparency"]["regions"]]
elif "priority" in j:
    shades = [p["shade"] for p in j["priority"]["order"]]
if sorted(shades) != fills:
    sys.exit(f"{sys.argv[2]}: fill colours differ from the JSON's shades")
PY
  fi
  rsvg-convert -b white "$W/$name.svg" -o "$W/$name.svg.png"
  for f in pdf png; do
    python3 "$HERE/picture_compare.py" same "$W/$name.$f" "$W/$name.svg" --bound 0.03 > "$W/cmp.txt" || { cat "$W/cmp.txt"; echo "$name: the $f differs from the SVG"; fail=1; }
    local c s
    c=$(python3 "$HERE/picture_compare.py" colours "$W/$name.$f" | awk '{print $2}')
    s=$(python3 "$HERE/picture_compare.py" colours "$W/$name.svg.png" | awk '{print $2}')
    if [ "$c" -lt 1000 ] || [ $((c * 10)) -lt $((s * 8)) ] || [ $((s * 10)) -lt $((c * 8)) ]; then
      echo "$name: the $f has $c coloured pixels, the SVG $s"; fail=1
    fi
  done
  echo "$name: $got fills in SVG, PDF and PNG"
}
check shadows 'sum(len(f["regions"]) for f in j["shadows"]["faces"])' "$D/shadows_demo.yaml" --shadows
check transparency 'len(j["transparency"]["regions"])' "$D/transparency_demo.yaml" --surfaces
check priority 'len(j["priority"]["order"])' "$D/three_sticks.yaml" --method priority
check surfaces '"any"' "$D/demo_lit.yaml" --surfaces
if [ "$fail" = 0 ]; then echo "products in writers: all drawn"; fi
exit "$fail"
