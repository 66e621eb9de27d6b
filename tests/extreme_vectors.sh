#!/usr/bin/env bash
# Vectors are directions: view, eye and up vectors of any size draw what the same
# direction of ordinary size draws, with both methods, and nothing is ever NaN or inf. Each
# case of the issue: --view 1e-400,1e-400,1e-400 / 1e-170,... / 1e155,... / 1e300,0,0,
# --up 1e-400,1e-400,0, --eye 1e160,1e160,1e160 (no NaN), a vertex 1e-40 in front of the eye
# plane, and two boxes with coordinates of 1e38 (the picture of the unit-sized boxes).
#   tests/extreme_vectors.sh HLR DATA_DIR
set -euo pipefail
HLR="$(realpath "$1")" D="$(realpath "$2")"
W="$(mktemp -d)"
trap 'rm -rf "$W"' EXIT
fail=0
same() {  # name, reference args, extreme args (both after the mesh)
  local name="$1" ref="$2" ext="$3" mesh="${4:-$D/cube.off}"
  for m in faces roberts; do
    # shellcheck disable=SC2086
    # --raw: one line per exact piece in segment order (pen order breaks ties between strokes at
    # equal distance by the doubles' last bits; the geometry is what must be the same).
    "$HLR" render "$mesh" --method $m $ref --edges all --hidden dashed --raw -o "$W/ref.svg" 2> /dev/null
    # shellcheck disable=SC2086
    "$HLR" render "$mesh" --method $m $ext --edges all --hidden dashed --raw -o "$W/ext.svg" 2> /dev/null || { echo "$name ($m): failed"; fail=1; continue; }
    if grep -q -i -E 'nan|inf[^o]' "$W/ext.svg"; then echo "$name ($m): NaN or inf in the drawing"; fail=1; fi
    if ! cmp -s "$W/ref.svg" "$W/ext.svg"; then echo "$name ($m): differs from $ref"; fail=1; fi
  done
}
same "view 1e-400" "--view 1,1,1" "--view 1e-400,1e-400,1e-400"
same "view 1e-170" "--view 1,2,3" "--view 1e-170,2e-170,3e-170"
same "view 1e155" "--view 1,1,1" "--view 1e155,1e155,1e155"
same "view 1e300 on an axis" "--view 1,0,0" "--view 1e300,0,0"
same "up 1e-400" "--view 1,1.3,1.7 --up 1,1,0" "--view 1,1.3,1.7 --up 1e-400,1e-400,0"
# A far eye: a valid perspective, no NaN.
for m in faces roberts; do
  "$HLR" render "$D/cube.off" --method $m --eye 1e160,1e160,1e160 -o "$W/far.svg" 2> /dev/null || { echo "far eye ($m): failed"; fail=1; }
  if grep -q -i -E 'nan|inf[^o]' "$W/far.svg"; then echo "far eye ($m): NaN or inf"; fail=1; fi
done
# A vertex 1e-40 in front of the plane through the eye.
printf 'OFF\n4 4 0\n0 0 1e-40\n1 0 1\n0 1 1\n1 1 2\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n' > "$W/near.off"
"$HLR" render "$W/near.off" --eye 0,0,0 --target 0,0,1 -o "$W/near.svg" 2> /dev/null || { echo "vertex 1e-40 in front of the eye: failed"; fail=1; }
if grep -q -i -E 'nan|inf[^o]' "$W/near.svg"; then echo "vertex 1e-40 in front of the eye: NaN or inf"; fail=1; fi
# Two boxes with coordinates of 1e38 draw the unit boxes' picture.
box() {  # file, scale
  printf 'OFF\n16 12 0\n' > "$1"
  for o in 0 3; do
    for b in 0 1 2 3 4 5 6 7; do
      echo "$(( o + (b & 1) ))$2 $(( (b >> 1) & 1 ))$2 $(( (b >> 2) & 1 ))$2" >> "$1"
    done
  done
  for o in 0 8; do
    printf '4 %d %d %d %d\n' $((o+0)) $((o+2)) $((o+3)) $((o+1)) $((o+4)) $((o+5)) $((o+7)) $((o+6)) $((o+0)) $((o+1)) $((o+5)) $((o+4)) \
      $((o+2)) $((o+6)) $((o+7)) $((o+3)) $((o+0)) $((o+4)) $((o+6)) $((o+2)) $((o+1)) $((o+3)) $((o+7)) $((o+5)) >> "$1"
  done
}
mkdir -p "$W/unit" "$W/e38"
box "$W/unit/boxes.off" ""
box "$W/e38/boxes.off" "e38"
for m in faces roberts; do
  "$HLR" render "$W/unit/boxes.off" --method $m --view 1,1.3,1.7 --hidden dashed -o "$W/u.svg" 2> /dev/null
  "$HLR" render "$W/e38/boxes.off" --method $m --view 1,1.3,1.7 --hidden dashed -o "$W/e.svg" 2> /dev/null || { echo "1e38 boxes ($m): failed"; fail=1; }
  if ! cmp -s "$W/u.svg" "$W/e.svg"; then echo "1e38 boxes ($m): differs from the unit boxes"; fail=1; fi
done
[ "$fail" = 0 ] && echo "extreme vectors: identical drawings, no NaN"
exit "$fail"
