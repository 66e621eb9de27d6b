#!/usr/bin/env bash
# Scaling a scene exactly changes nothing in its drawing: a tetrahedron (and the eye)
# scaled by 1e300, 1e-400 and a 30-digit integer draws exactly the unit tetrahedron's picture,
# with every method, orthographic and perspective: the same SVG, and in the JSON the same
# pieces (parameters and visibility). No output may hold NaN or inf.
#   tests/scaled_numbers.sh HLR
set -euo pipefail
HLR="$(realpath "$1")"
W="$(mktemp -d)"
trap 'rm -rf "$W"' EXIT
fail=0
for s in 1 1e300 1e-400 123456789012345678901234567890; do
  mkdir -p "$W/$s"
  printf 'OFF\n4 4 0\n0 0 0\n%s 0 0\n0 %s 0\n0 0 %s\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n' "$s" "$s" "$s" > "$W/$s/tet.off"
  eye="2*$s"
  e1=$(python3 -c "from fractions import Fraction as F; s=F('$s'); print(','.join(str(k*s) for k in (2,3,4)))")
  for m in faces roberts; do
    "$HLR" render "$W/$s/tet.off" --method $m --view 1,1.3,1.7 --hidden dashed --edges all -o "$W/$s/o_$m.svg"
    "$HLR" render "$W/$s/tet.off" --method $m --eye "$e1" --target 0,0,0 --hidden dashed --edges all -o "$W/$s/p_$m.svg"
    "$HLR" render "$W/$s/tet.off" --method $m --eye "$e1" --target 0,0,0 --edges all -o "$W/$s/p_$m.json"
    "$HLR" render "$W/$s/tet.off" --method $m --view 1e-400,13e-401,17e-401 --edges all -o "$W/$s/v_$m.svg"
    grep '"body"' "$W/$s/p_$m.json" | sed 's/"from":\[[^]]*\],"to":\[[^]]*\],//' > "$W/$s/p_$m.pieces"
  done
  if grep -l -i -E 'nan|inf"' "$W/$s"/*.svg; then echo "NaN or inf in the drawing of the tetrahedron scaled by $s"; fail=1; fi
  if [ "$s" != 1 ]; then
    for f in o_faces.svg o_roberts.svg p_faces.svg p_roberts.svg v_faces.svg v_roberts.svg p_faces.pieces p_roberts.pieces; do
      if ! cmp -s "$W/1/$f" "$W/$s/$f"; then echo "scaled by $s: $f differs from the unit tetrahedron's"; diff "$W/1/$f" "$W/$s/$f" | head -5; fail=1; fi
    done
  fi
done
[ "$fail" = 0 ] && echo "scaled tetrahedra: identical drawings"
exit "$fail"
