#!/usr/bin/env bash
# Output does not depend on the thread count: the same bytes with --threads 1, 2
# and 8 for line drawings (SVG with hidden lines, exact JSON, DXF with cut dashes, PDF) of a sphere, a cloud of
# interpenetrating cubes and 400 random triangles (intersection lines, many cuts), the
# visible surfaces (--surfaces), a raster (PNG and face ids) and a horizon (SVG and JSON).
# The same bytes again with HLR_MALLOC=system (no huge pages) and =restart (the settings a
# large job gets, here for small ones), and the restart's settings are the ones
# cli/process.cpp names, for large jobs only, a user's own left alone.
# Usage: tests/thread_identity.sh HLR GEN_MESH DATA_DIR
set -euo pipefail
hlr="$1"; gen="$2"; data="$3"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
"$gen" sphere 40 > "$work/sphere.off"
"$gen" cubes 6 > "$work/cubes.off"
"$gen" triangles 400 7 > "$work/tris.off"
fail=0
same() {  # name, then the command with THREADS where the count goes
  local name="$1"; shift
  local first=""
  for t in 1 2 8; do
    local out="$work/$name.$t"
    "${@//THREADS/$t}" > "$out" 2> "$work/err" || { echo "$name: --threads $t failed: $(cat "$work/err")"; fail=1; return; }
    if [ -z "$first" ]; then first="$out"; elif ! cmp -s "$first" "$out"; then echo "$name: --threads $t differs from --threads 1"; fail=1; fi
  done
  # glibc's own malloc settings instead of the huge pages hlr sets for itself (cli/process.cpp)
  HLR_MALLOC=system "${@//THREADS/2}" > "$work/$name.system" 2> "$work/err" || { echo "$name: HLR_MALLOC=system failed"; fail=1; return; }
  cmp -s "$first" "$work/$name.system" || { echo "$name: HLR_MALLOC=system differs"; fail=1; }
  HLR_MALLOC=restart "${@//THREADS/2}" > "$work/$name.restart" 2> "$work/err" || { echo "$name: HLR_MALLOC=restart failed"; fail=1; return; }
  cmp -s "$first" "$work/$name.restart" || { echo "$name: HLR_MALLOC=restart differs"; fail=1; }
  echo "$name: identical on 1, 2 and 8 threads ($(wc -c < "$first") bytes)"
}
for m in sphere cubes tris; do
  same "$m.svg" "$hlr" render "$work/$m.off" --view 1,1.3,1.7 --hidden dashed --threads THREADS
  same "$m.json" "$hlr" render "$work/$m.off" --view 1,1.3,1.7 --format json --threads THREADS
  same "$m.dxf" "$hlr" render "$work/$m.off" --view 1,1.3,1.7 --hidden dashed --dashes geometry --format dxf --threads THREADS
  same "$m.pdf" "$hlr" render "$work/$m.off" --view 1,1.3,1.7 --hidden dashed --format pdf --threads THREADS
done
same "demo-views.pdf" "$hlr" render "$data/demo.yaml" --views front,top,right,iso --page A3 --hidden dashed --format pdf --threads THREADS
same "demo-surfaces.svg" "$hlr" render "$data/demo_lit.yaml" --surfaces --threads THREADS
for t in 1 2 8; do
  "$hlr" raster "$work/sphere.off" --size 160x120 --samples 2 --ids "$work/ids.$t.png" --threads "$t" -o "$work/raster.$t.png" 2> "$work/err" \
    || { echo "raster: --threads $t failed: $(cat "$work/err")"; fail=1; }
  for f in raster ids; do
    cmp -s "$work/$f.1.png" "$work/$f.$t.png" || { echo "raster $f: --threads $t differs from --threads 1"; fail=1; }
  done
done
echo "raster PNG and face ids: compared on 1, 2 and 8 threads"
same "horizon.svg" "$hlr" horizon --expr "sin(5*x)*cos(4*z)/3" --x -1:1:200 --z -1:1:60 --hidden dashed --threads THREADS
same "horizon.json" "$hlr" horizon --expr "sin(5*x)*cos(4*z)/3" --x -1:1:60 --z -1:1:20 --format json --threads THREADS
# The restart: hlr's settings when none are given, for a large job (an input over 8 MiB: a
# sparse file is enough, the settings are chosen before it is read); a small job sets them in
# process; a user's glibc.malloc.hugetlb left as it is.
truncate -s 9M "$work/large.off"
shown="$(HLR_MALLOC=show "$hlr" info "$work/large.off" 2>&1 >/dev/null | head -1 || true)"
case "$shown" in
  *"glibc.malloc.hugetlb=1:glibc.malloc.top_pad=268435456:glibc.malloc.trim_threshold=4294967295:glibc.malloc.mmap_threshold=33554432:glibc.malloc.mmap_max=0") echo "huge pages, large job: $shown" ;;
  *) echo "huge pages: not set by the restart for a large job: '$shown'"; fail=1 ;;
esac
printf 'bodies:\n  - mesh: "large.off"\n' > "$work/large.yaml"
shown="$(HLR_MALLOC=show "$hlr" info "$work/large.yaml" 2>&1 >/dev/null | head -1 || true)"
case "$shown" in
  *"glibc.malloc.hugetlb=1"*) echo "huge pages, scene naming a large mesh: restarted" ;;
  *) echo "huge pages: a scene naming a large mesh was not restarted: '$shown'"; fail=1 ;;
esac
for small in "--version" "info $work/sphere.off" "render $data/demo.yaml -o $work/demo.svg"; do
  shown="$(HLR_MALLOC=show "$hlr" $small 2>&1 >/dev/null | head -1 || true)"
  case "$shown" in
    "hlr: in process: mmap_threshold=33554432 top_pad=268435456"*) ;;
    *) echo "huge pages: small job 'hlr $small' not set in process: '$shown'"; fail=1 ;;
  esac
done
echo "huge pages, small jobs: set in process"
shown="$(GLIBC_TUNABLES=glibc.malloc.hugetlb=0 HLR_MALLOC=show "$hlr" --version 2>&1 >/dev/null || true)"
[ "$shown" = "hlr: GLIBC_TUNABLES=glibc.malloc.hugetlb=0" ] || { echo "huge pages: a user's setting changed: '$shown'"; fail=1; }
[ "$fail" = 0 ] && echo "thread identity: all identical"
exit "$fail"
