#!/usr/bin/env bash
# Behaviour check for refactors: runs every bundled design (assets/designs/README.md) through two
# paver binaries, on the CPU and on Vulkan (lavapipe when no GPU), and compares placements.csv,
# elements.ply, elements.obj and design.json byte for byte. Exit 0 when all are identical.
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
runs=0 differ=0
while IFS='|' read -r _ design surface _; do
  design=$(echo $design) surface=$(echo $surface)
  for backend in $backends; do
    for side in old new; do
      bin=$old; [ $side = new ] && bin=$new
      "$bin" run "assets/surfaces/$surface" --design "assets/designs/$design" --backend "$backend" \
        --out "$work/$side" > /dev/null || [ $? = 3 ]  # 3: written, verdict NOT OK
    done
    runs=$((runs + 1))
    for file in placements.csv elements.ply elements.obj design.json; do
      if ! cmp -s "$work/old/$file" "$work/new/$file"; then
        echo "DIFFERS: $design ($backend): $file"
        differ=$((differ + 1))
      fi
    done
  done
done < <(grep -E '^\| [a-z0-9_]+\.json' assets/designs/README.md)
echo "$runs runs (designs x backends: $backends), $differ files differ"
[ $differ -eq 0 ]
