#!/usr/bin/env bash
# Speed of two commits in one run on this machine: builds one benchmark binary of each commit in
# a temporary worktree (Release), runs both with the same filter one after the other, and prints
# each benchmark's real time and the ratio new / old (below 1: the new commit is faster). Only
# ratios from one run compare like with like; the worktrees are removed on exit.
# Usage: bench/compare_commits.sh OLD NEW [BINARY] [FILTER]
#   e.g. bench/compare_commits.sh f3af651 HEAD paver-solver-bench solver_shape
#        bench/compare_commits.sh HEAD~3 HEAD paver-bench pave/
set -euo pipefail
cd "$(dirname "$0")/.."
[ $# -ge 2 ] || { echo "usage: bench/compare_commits.sh OLD NEW [BINARY] [FILTER]" >&2; exit 2; }
old=$1 new=$2 binary=${3:-paver-bench} filter=${4:-.}
for rev in "$old" "$new"; do
  git rev-parse --verify --quiet "$rev^{commit}" >/dev/null || { echo "bench/compare_commits.sh: $rev is no commit here" >&2; exit 2; }
done
work=$(mktemp -d)
cleanup() {
  for side in old new; do [ -d "$work/$side" ] && git worktree remove --force "$work/$side" >/dev/null 2>&1; done
  rm -rf "$work"
}
trap cleanup EXIT
for side in old new; do
  rev=$([ "$side" = old ] && echo "$old" || echo "$new")
  git worktree add --detach "$work/$side" "$rev" >/dev/null 2>&1
  echo "building $binary at $rev ..." >&2
  cmake -S "$work/$side" -B "$work/$side/build" -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
  cmake --build "$work/$side/build" --target "$binary" >/dev/null
done
for side in old new; do
  echo "running $side ..." >&2
  "$work/$side/build/bin/$binary" --benchmark_filter="$filter" --benchmark_format=csv 2>/dev/null |
    grep -v '^name,' | grep ',' > "$work/$side.csv" || true
done
echo "| benchmark | $old | $new | new / old |"
echo "|---|---:|---:|---:|"
# CSV columns: name, iterations, real_time, cpu_time, time_unit, ...; names are quoted.
awk -F, 'NR == FNR { old[$1] = $3; unit[$1] = $5; next }
         ($1 in old) { gsub(/"/, "", $1); n = $1; printf "| %s | %.4g %s | %.4g %s | %.3f |\n", n, old["\"" n "\""], $5, $3, $5, $3 / old["\"" n "\""] }' \
  "$work/old.csv" "$work/new.csv"
