#!/usr/bin/env bash
# Compares the readings of the paper's ambiguous points (docs/solver.md) over every bundled
# design: runs `paver run` per variant and prints one markdown row per variant with the sums
# over designs. Usage: bench/compare_readings.sh [build/bin/paver]
set -euo pipefail
cd "$(dirname "$0")/.."
paver=${1:-build/bin/paver}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
variants=(
  "default|"
  "filter clamp on l_ab at initialisation|--filter-base initial"
  "no filter (filter_max 1)|--filter-max 1"
  "strays pulled back only (never retired)|--stray-patience 0"
  "dt 0.5 (the paper's Table 1 value)|--dt 0.5"
  "stretched springs at the paper's 0.5|--mu-stretched 0.5"
)
echo "| reading | designs with collisions (paper's forces) | collisions (paper's forces) | worst NN p5 | collisions after contact springs | elements removed | elements | solver ms |"
echo "|---|---:|---:|---:|---:|---:|---:|---:|"
for variant in "${variants[@]}"; do
  label=${variant%%|*}; flags=${variant#*|}
  rows=()
  while IFS='|' read -r _ design surface _; do
    design=$(echo "$design" | tr -d ' '); surface=$(echo "$surface" | tr -d ' ')
    [[ $design == *.json ]] || continue
    # shellcheck disable=SC2086
    # Exit 3 (verdict NOT OK) still wrote the readings.
    rc=0
    "$paver" run "assets/surfaces/$surface" --design "assets/designs/$design" --out "$out/$design" $flags > /dev/null 2>&1 \
      || rc=$?
    [[ $rc == 0 || $rc == 3 ]] || { rows+=("FAIL"); continue; }
    rows+=("$out/$design/report.json")
  done < assets/designs/README.md
  python3 - "$label" "${rows[@]}" <<'PY'
import json, sys
label, files = sys.argv[1], sys.argv[2:]
fails = files.count("FAIL")
reports = [json.load(open(f)) for f in files if f != "FAIL"]
paper = [r["quality_paper_method"]["contact_violations"] for r in reports]
print("| %s | %d of %d | %d | %.3f | %d | %d | %d | %.0f |%s" % (
    label, sum(1 for c in paper if c), len(reports), sum(paper),
    min(r["quality_paper_method"]["neighbor_ratio"]["p5"] for r in reports),
    sum(r["quality_after"]["contact_violations"] for r in reports),
    sum(r["collision_resolution"]["removed"] for r in reports),
    sum(r["quality_after"]["elements"] for r in reports),
    sum(r["optimization"]["milliseconds"] for r in reports),
    " (%d failed)" % fails if fails else ""))
PY
done
