#!/usr/bin/env bash
# Regenerates paper_figures/: runs every experiment at paper scale, copies each figure (PNG) and
# writes the check table of that run to paper_figures/CHECK.md. Run after any physics change.
set -euo pipefail
cd "$(dirname "$0")/.."
out=${OUT:-out-paper}
./build/granrepro all --scale paper --threads "$(nproc)" --out "$out" --quiet > /dev/null || true
mkdir -p paper_figures
for dir in "$out"/*/; do
  cp "$dir"/*.png paper_figures/ 2>/dev/null || true
done
{
  echo "# Check table of the paper-scale run that made these figures"
  echo
  echo "Code version: $(./build/granrepro --version), $(date -u +%Y-%m-%d)."
  echo
  echo '```'
  ./build/granrepro check --all --out "$out" || true
  echo '```'
} > paper_figures/CHECK.md
echo "paper_figures/ updated from $out"
