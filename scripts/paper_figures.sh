#!/usr/bin/env bash
# Regenerates paper_figures/ from paper-scale runs.
#   scripts/paper_figures.sh                 run every experiment at paper scale, then collect
#   scripts/paper_figures.sh cooling ...     run only these, then collect from all runs present
#   scripts/paper_figures.sh --collect       run nothing, only collect the runs present
# Runs go to $OUT (default out-paper/); each figure's PNG is copied to paper_figures/ and the check
# table of all runs present is written to paper_figures/CHECK.md. Run after any physics change.
set -euo pipefail
cd "$(dirname "$0")/.."
out=${OUT:-out-paper}
threads=$(nproc)
if [ "${1:-}" = "--collect" ]; then
  :
elif (($#)); then
  for e in "$@"; do ./build/granrepro "$e" --scale paper --threads "$threads" --out "$out" --quiet > /dev/null; done
else
  ./build/granrepro all --scale paper --threads "$threads" --out "$out" --quiet > /dev/null || true
fi
mkdir -p paper_figures
{
  echo "# Check table of the paper-scale runs that made these figures"
  echo
  echo "Made by scripts/paper_figures.sh; the code version and wall time of each run are in its data.h5."
  echo
  echo '```'
  for dir in "$out"/*/; do
    name=$(basename "$dir")
    [ -f "$dir/summary.json" ] || continue
    cp "$dir"/*.png paper_figures/ 2>/dev/null || true
    version=$(python3 -c "import json,sys; d=json.load(open('$dir/summary.json')); print(d['code_version'], '%.0f s' % d['wall_time_s'])" 2>/dev/null || echo "?")
    echo "# $name: $version"
    ./build/granrepro check "$name" --out "$out" || true
    echo
  done
  echo '```'
} > paper_figures/CHECK.md
echo "paper_figures/ updated from $out"
