#!/usr/bin/env bash
# Regenerates paper_figures/ from paper-scale runs.
#   scripts/paper_figures.sh                 run every experiment at paper scale, then collect
#   scripts/paper_figures.sh cooling ...     run only these, then collect from all runs present
#   scripts/paper_figures.sh --collect       run nothing, only collect the runs present
# Runs go to $OUT (default out-paper/). For each run present, its figures' PNGs are copied to
# paper_figures/, and its summary.json with a compact data.h5 (every parameter, scalar and curve;
# particle snapshots left out, see `granrepro export --help`) to paper_figures/<experiment>/.
# paper_figures/CHECK.md is the check table of those committed numbers, made by the same command
# CI runs (`granrepro check --all --out paper_figures`), so a change to expected/ that the
# committed paper-scale results no longer satisfy fails CI. Run after any physics change.
set -euo pipefail
cd "$(dirname "$0")/.."
out=${OUT:-out-paper}
threads=$(nproc)
max_mb=20
if [ "${1:-}" = "--collect" ]; then
  :
elif (($#)); then
  for e in "$@"; do ./build/granrepro "$e" --scale paper --threads "$threads" --out "$out" --quiet > /dev/null || true; done
else
  ./build/granrepro all --scale paper --threads "$threads" --out "$out" --quiet > /dev/null || true
fi
mkdir -p paper_figures
for dir in "$out"/*/; do
  name=$(basename "$dir")
  [ -f "$dir/summary.json" ] || continue
  # The path goes in as an argument, never into the Python text (a folder name is not code).
  scale=$(python3 -c 'import json, sys; print(json.load(open(sys.argv[1]))["scale"])' "$dir/summary.json")
  if [ "$scale" != paper ]; then
    echo "paper_figures: skipping $dir ($scale scale)" >&2
    continue
  fi
  cp "$dir"/*.png paper_figures/ 2>/dev/null || true
  ./build/granrepro export "$name" --out "$out" --to paper_figures
done
{
  echo "# Check table of the paper-scale runs that made these figures"
  echo
  echo "Made by scripts/paper_figures.sh from the committed paper_figures/<experiment>/summary.json;"
  echo "the code version and wall time of each run are in its data.h5. Re-check with"
  echo "\`./build/granrepro check --all --out paper_figures\` (\`--explain\` prints the known deviations)."
  echo
  echo '```'
  for dir in paper_figures/*/; do
    name=$(basename "$dir")
    [ -f "$dir/summary.json" ] || continue
    version=$(python3 -c 'import json, sys; d = json.load(open(sys.argv[1])); print(d["code_version"], "seed", d["seed"], "%.0f s" % d["wall_time_s"])' \
                "$dir/summary.json" 2>/dev/null || echo "?")
    echo "# $name: $version"
    ./build/granrepro check "$name" --out paper_figures --explain || true
    echo
  done
  ./build/granrepro check --all --missing-ok --out paper_figures 2>&1 | grep -E '^totals:|no results' || true
  echo '```'
} > paper_figures/CHECK.md
size_kb=$(du -sk paper_figures | cut -f1)
if ((size_kb > max_mb * 1024)); then
  echo "paper_figures/ is $((size_kb / 1024)) MB, above the ${max_mb} MB limit: lower --max-table-values of the export" >&2
  exit 1
fi
echo "paper_figures/ updated from $out ($((size_kb / 1024)) MB)"
