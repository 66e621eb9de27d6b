#!/usr/bin/env bash
# Start-up and drawing sets: what a small job costs, whole process, and what a set of views
# costs against one. Each row runs every hlr given (e.g. a build before and after a change) in
# alternating runs, best of 5 wall seconds each (GNU time), with peak memory. Rows: `hlr
# --version`; the unit cube; bunny00 (75k triangles) one view; its four views as a sheet
# (--views) and as a batch of four files (--view with -o, repeated; a build without batches
# draws them as four processes); screw.step one view and four as a batch. Writes
# build/bench/startup.md.
# Usage: scripts/bench_startup.sh [HLR ...]   (default: build/hlr)
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BUILD="${HLR_BUILD_DIR:-$ROOT/build}"
OUT="$BUILD/bench"
[ $# -gt 0 ] || set -- "$BUILD/hlr"
for h in "$@"; do [ -x "$h" ] || { echo "bench_startup: $h is not a program" >&2; exit 1; }; done
command -v /usr/bin/time >/dev/null || { echo "bench_startup: needs GNU time (apt install time)" >&2; exit 1; }
MESHES="$(cd "$("$ROOT/scripts/extract_corpus.sh")" && pwd)"
STEP=/usr/share/opencascade/data/step/screw.step
mkdir -p "$OUT"
BUNNY="$MESHES/bunny00.off"
VIEWS=(front top right iso)

# One run of a job with program $1: prints "wall_s peak_KB" (a set of processes: summed wall,
# largest peak).
run_job() {
  local h="$1" job="$2" wall=0 peak=0
  case "$job" in
    version) cmds=("$h --version") ;;
    cube) cmds=("$h render $ROOT/data/cube.off -o $OUT/s.svg") ;;
    bunny_one) cmds=("$h render $BUNNY --view iso -o $OUT/s.svg") ;;
    bunny_sheet) cmds=("$h render $BUNNY --views front,top,right,iso -o $OUT/s.svg") ;;
    bunny_batch | step_batch)
      local input="$BUNNY"
      [ "$job" = step_batch ] && input="$STEP"
      if "$h" render "$ROOT/data/cube.off" --view front -o "$OUT/b1.svg" --view top -o "$OUT/b2.svg" 2>/dev/null; then
        local c="$h render $input"
        for v in "${VIEWS[@]}"; do c="$c --view $v -o $OUT/b_$v.svg"; done
        cmds=("$c")
      else  # no batches in this build: four processes
        cmds=()
        for v in "${VIEWS[@]}"; do cmds+=("$h render $input --view $v -o $OUT/b_$v.svg"); done
      fi
      ;;
    step_one) cmds=("$h render $STEP --view iso -o $OUT/s.svg") ;;
  esac
  for c in "${cmds[@]}"; do
    # shellcheck disable=SC2086
    /usr/bin/time -f "%e %M" -o "$OUT/time.txt" $c >/dev/null 2>&1
    read -r w kb <"$OUT/time.txt"
    wall=$(awk "BEGIN{print $wall + $w}")
    [ "$kb" -gt "$peak" ] && peak=$kb
  done
  echo "$wall $peak"
}

jobs=(version cube bunny_one bunny_sheet bunny_batch)
[ -e "$STEP" ] && jobs+=(step_one step_batch)
report="$OUT/startup.md"
{
  echo "# Start-up and drawing sets ($(date -u +%Y-%m-%d), $(nproc) cores, $(awk '/MemTotal/{printf "%d GiB", $2/1048576}' /proc/meminfo))"
  echo
  echo "Whole process, best of 5 in alternating runs; wall s, peak MB."
  echo
  header="| job |"
  rule="|---|"
  for h in "$@"; do header="$header $h |"; rule="$rule---|"; done
  echo "$header"
  echo "$rule"
  for job in "${jobs[@]}"; do
    declare -A best=() mem=()
    for _ in 1 2 3 4 5; do
      for h in "$@"; do
        read -r w kb < <(run_job "$h" "$job")
        if [ -z "${best[$h]:-}" ] || awk "BEGIN{exit !($w < ${best[$h]})}"; then best[$h]=$w; fi
        mem[$h]=$((kb / 1024))
      done
    done
    row="| $job |"
    for h in "$@"; do row="$row ${best[$h]} s, ${mem[$h]} MB |"; done
    echo "$row"
    unset best mem
  done
} | tee "$report"
echo "bench_startup: $report" >&2
