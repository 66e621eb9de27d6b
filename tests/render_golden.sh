#!/usr/bin/env bash
# Golden-file test of `hlr render` output: the demo scene and three CGAL meshes
# (fandisk, couplingdown, cross), each as SVG and JSON, orthographic and perspective, both
# methods where they apply. The outputs must stay byte-identical across refactorings: the
# demo's files are compared whole (tests/golden/render/*.svg|json), the meshes' by SHA-256
# (tests/golden/render/SHA256SUMS; the meshes are not committed, see scripts/extract_corpus.sh).
# The JSON's work counters of the filters (pairs tested and skipped, parameter comparisons)
# measure work, not the answer: they are blanked before comparing, so tuning a filter does not
# change a golden file while any change of the drawing or of the other statistics does.
#   tests/render_golden.sh HLR DATA_DIR CORPUS_DIR GOLDEN_DIR [--update]
set -euo pipefail
HLR="$(realpath "$1")" D="$(realpath "$2")" M="$(realpath "$3")" G="$(realpath "$4")/render"
UPDATE="${5:-}"
OUT="$(mktemp -d)"
trap 'rm -rf "$OUT"' EXIT
# The JSON names each body's source file: run on copies under fixed relative paths, so that the
# output does not depend on where the checkout or the build lives.
mkdir -p "$OUT/in/data" "$OUT/in/meshes"
cp "$D"/*.yaml "$D"/*.off "$D"/*.obj "$OUT/in/data/"
cp "$M/fandisk.off" "$M/couplingdown.off" "$M/cross.off" "$OUT/in/meshes/"
cd "$OUT/in"
run() {  # name, args...
  local name="$1"
  shift
  "$HLR" render "$@" -o "$OUT/$name" 2> "$OUT/$name.stderr"
  case "$name" in
    *.json) sed -i -E 's/"(pairs_tested|pairs_skipped_by_prefilter|parameter_comparisons[a-z_]*|intersection_pairs_tested)":[0-9]+/"\1":"_"/g' "$OUT/$name" ;;
  esac
}
run demo.svg data/demo.yaml --hidden dashed
run demo.json data/demo.yaml
run demo_roberts.json data/demo.yaml --method roberts --view 1,1.3,1.7
run demo_perspective.svg data/demo.yaml --eye 9,-7,6 --hidden dashed
run fandisk.svg meshes/fandisk.off --view 1,1.3,1.7 --hidden dashed
run fandisk.json meshes/fandisk.off --view 1,1.3,1.7 --crease 40
run couplingdown_all.json meshes/couplingdown.off --view 0,0,1 --edges all
run couplingdown_perspective.svg meshes/couplingdown.off --eye 3,4,5 --hidden dashed
run cross_roberts.json meshes/cross.off --method roberts --view 1,2,3
run cross_faces.json meshes/cross.off --view 1,2,3
cd "$OUT"
if [ "$UPDATE" = --update ]; then
  mkdir -p "$G"
  cp demo.svg demo.json demo_roberts.json demo_perspective.svg "$G/"
  sha256sum fandisk.svg fandisk.json couplingdown_all.json couplingdown_perspective.svg cross_roberts.json cross_faces.json > "$G/SHA256SUMS"
  echo "golden files updated in $G"
  exit 0
fi
fail=0
for f in demo.svg demo.json demo_roberts.json demo_perspective.svg; do
  if ! cmp -s "$f" "$G/$f"; then
    echo "render output differs from the golden file: $f"
    diff "$G/$f" "$f" | head -20
    fail=1
  fi
done
if ! sha256sum --quiet -c "$G/SHA256SUMS"; then fail=1; fi
[ "$fail" = 0 ] && echo "render golden files: all identical"
exit "$fail"
