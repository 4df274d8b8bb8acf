#!/usr/bin/env bash
# Behaviour check for refactors: runs every bundled design (assets/designs/README.md), and the runs
# below that take each automatic choice (band rows, topology, offset fit, cut axis, rim rows,
# beads), through two paver binaries, on the CPU and on Vulkan (lavapipe when no GPU), and
# compares placements.csv, elements.ply, elements.obj and design.json byte for byte. Exit 0 when
# all are identical.
# Usage: bench/compare_placements.sh OLD_PAVER NEW_PAVER
#   e.g. git worktree add /tmp/old <commit> && (cd /tmp/old && app/setup.sh build)
#        bench/compare_placements.sh /tmp/old/build/bin/paver build/bin/paver
set -euo pipefail
cd "$(dirname "$0")/.."
[ $# -eq 2 ] || { echo "usage: bench/compare_placements.sh OLD_PAVER NEW_PAVER" >&2; exit 2; }
old=$1 new=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
backends="cpu"
"$new" devices > /dev/null 2>&1 && backends="cpu vulkan"
# surface | flags: each takes a choice the bundled designs do not.
choices=(
  "ring_band.obj|--stone 1.5 --gap 0.1"                                   # band rows auto, stones kept
  "bangle.obj|--stone 1.3 --gap 0.1 --rim-rows all"                       # band, rim rows on both rims
  "vase_band.obj|"                                                        # band at the default spacing
  "bead.obj|--stone 1.2 --gap 0.1"                                        # closed: charts, cut axis auto
  "facade_windows.obj|--design assets/designs/facade_windows_grid_discs.json --align x --fit-offset"
  "pendant_pierced.obj|--stone 1.5 --gap 0.1 --margin 0.3 --rim-rows holes --beads"
  "saddle.obj|--pattern tri --topology adaptive"                          # the grown pattern
  "../scanned/bunnyhead.obj|--pattern tri"                                # topology auto takes the adaptive
)
runs=0 differ=0
run_both() {  # label, then the arguments after `paver run`
  local label=$1 backend
  shift
  for backend in $backends; do
    for side in old new; do
      bin=$old; [ $side = new ] && bin=$new
      rm -rf "$work/$side"
      "$bin" run "$@" --backend "$backend" --out "$work/$side" --quiet > /dev/null || [ $? = 3 ]  # 3: NOT OK
    done
    runs=$((runs + 1))
    for file in placements.csv elements.ply elements.obj design.json; do
      if ! cmp -s "$work/old/$file" "$work/new/$file"; then
        echo "DIFFERS: $label ($backend): $file"
        differ=$((differ + 1))
      fi
    done
  done
}
while IFS='|' read -r _ design surface _; do
  design=$(echo $design) surface=$(echo $surface)
  run_both "$design" "assets/surfaces/$surface" --design "assets/designs/$design"
done < <(grep -E '^\| [a-z0-9_]+\.json' assets/designs/README.md)
for choice in "${choices[@]}"; do
  surface=${choice%%|*} flags=${choice#*|}
  # shellcheck disable=SC2086 # the flags are words
  run_both "$surface $flags" "assets/surfaces/$surface" $flags
done
echo "$runs runs (designs and choices x backends: $backends), $differ files differ"
[ $differ -eq 0 ]
