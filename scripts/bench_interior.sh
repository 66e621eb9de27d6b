#!/usr/bin/env bash
# Interior views benchmark: `hlr render --surfaces` (and with --shadows) of a scene seen from
# inside (the eye among the bodies: every body cut at the near plane, a lamp's six cube views)
# against the same camera on the scene without the boxes that reach the eye's plane (what the
# view costs when nothing needs the cut: the bodies in front, as from outside), whole process,
# best of 3 each, with peak memory (GNU time). Scenes: data/interior_lit.yaml, the house of
# data/house.yaml seen from its living room, and the lit room with CGAL's bunny00 (75k
# triangles) on the table. Writes build/bench/interior.md.
# Usage: scripts/bench_interior.sh
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BUILD="${HLR_BUILD_DIR:-$ROOT/build}"
HLR="$BUILD/hlr"
OUT="$BUILD/bench"
[ -x "$HLR" ] || { echo "bench_interior: build first (scripts/setup.sh)" >&2; exit 1; }
command -v /usr/bin/time >/dev/null || { echo "bench_interior: needs GNU time (apt install time)" >&2; exit 1; }
MESHES="$(cd "$("$ROOT/scripts/extract_corpus.sh")" && pwd)"
mkdir -p "$OUT"
# The lit room with the bunny on the table.
{
  sed -n '/^bodies:/,/^camera:/p' "$ROOT/data/interior_lit.yaml" | sed '$d'
  printf '  - name: bunny\n    mesh: %s\n    transform:\n      - rotate: {axis: x, degrees: 90}\n      - translate: [3.25, 2.5, 1.25]\n' "$MESHES/bunny00.off"
  sed -n '/^camera:/,$p' "$ROOT/data/interior_lit.yaml"
} > "$OUT/interior_bunny.yaml"
# A scene without its boxes that reach the eye's plane (boxes written {min: [..], max: [..]}).
in_front() {  # SCENE EYE TARGET OUT
  python3 - "$@" <<'PY'
import re, sys
src, eye, target, out = sys.argv[1], [float(x) for x in sys.argv[2].split(",")], [float(x) for x in sys.argv[3].split(",")], sys.argv[4]
f = [t - e for t, e in zip(target, eye)]
lines, keep, body = open(src).read().split("\n"), [], []
def flush():
    text = "\n".join(body)
    m = re.search(r"min: \[([^]]*)\], max: \[([^]]*)\]", text)
    if m:
        lo, hi = [[eval(x) for x in g.split(",")] for g in m.groups()]
        corners = [[(lo, hi)[(i >> k) & 1][k] for k in range(3)] for i in range(8)]
        if min(sum((c[k] - eye[k]) * f[k] for k in range(3)) for c in corners) <= 0: return
    keep.extend(body)
for line in lines:
    if line.startswith("  - "): flush(); body = [line]
    elif body and line.startswith("    "): body.append(line)
    else: flush(); body = []; keep.append(line)
flush()
open(out, "w").write("\n".join(keep))
PY
}
best() {  # best of 3: "wall_s peak_MB"
  local b="" m=0
  for _ in 1 2 3; do
    /usr/bin/time -f "%e %M" -o "$OUT/time.txt" "$HLR" render "$@" -o "$OUT/out.svg" 2>/dev/null >/dev/null
    read -r wall kb < "$OUT/time.txt"
    if [ -z "$b" ] || awk "BEGIN{exit !($wall < $b)}"; then b=$wall; fi
    m=$((kb / 1024))
  done
  echo "$b $m"
}
report="$OUT/interior.md"
{
  echo "# hlr render from inside and from outside ($(date -u +%Y-%m-%d), $(nproc) cores, $(awk '/MemTotal/{printf "%d GiB", $2/1048576}' /proc/meminfo))"
  echo
  echo "| scene | product | bodies in front: s, MB | inside: s, MB | ratio |"
  echo "|---|---|---|---|---|"
  for scene in interior_lit house interior_bunny; do
    case "$scene" in
      interior_lit) file="$ROOT/data/interior_lit.yaml"; eye=1,0.5,1.6; target=4,3,1.2 ;;
      house) file="$ROOT/data/house.yaml"; eye=1.2,1,1.6; target=6,2.5,1.2 ;;
      interior_bunny) file="$OUT/interior_bunny.yaml"; eye=1,0.5,1.6; target=4,3,1.2 ;;
    esac
    cam=(--eye "$eye" --target "$target" --up 0,0,1 --fov 90)
    in_front "$file" "$eye" "$target" "$OUT/${scene}_front.yaml"
    for product in "--surfaces" "--surfaces --shadows"; do
      read -r -a p <<< "$product"
      read -r ow om < <(best "$OUT/${scene}_front.yaml" "${cam[@]}" "${p[@]}")
      read -r iw im < <(best "$file" "${cam[@]}" "${p[@]}")
      echo "| $scene | \`$product\` | $ow, $om | $iw, $im | $(awk "BEGIN{printf \"%.2f\", $iw/$ow}") |"
    done
  done
} > "$report"
cat "$report"
