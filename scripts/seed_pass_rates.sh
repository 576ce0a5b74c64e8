#!/usr/bin/env bash
# How robust is each quick-scale verdict against the seed? Runs every experiment at quick scale
# for seeds 1..N (default 5) and prints, per claim, how many seeds gave PASS, DEVIATION, FAIL
# (skipped claims are left out), the least robust first.
#   scripts/seed_pass_rates.sh [--strict] [N] [EXPERIMENT...]   runs go to $OUT (default out-seeds/)
# --strict: exit 1 if any claim judged at quick scale FAILs for any seed (a claim CI judges must
# hold for every seed; ctest repro.seed_pass_rates runs this with N = 5).
# Needs $GRANREPRO (default "$bin", which scripts/main.sh builds). Takes N times the
# quick run (~1 min each).
set -euo pipefail
cd "$(dirname "$0")/.."
strict=0
if [ "${1:-}" = "--strict" ]; then strict=1; shift; fi
n=${1:-5}
shift || true
bin=${GRANREPRO:-./build/granrepro}
out=${OUT:-out-seeds}
threads=$(nproc)
for ((s = 1; s <= n; s++)); do
  if (($#)); then
    for e in "$@"; do "$bin" "$e" --scale quick --seed "$s" --threads "$threads" --quiet --out "$out/seed$s" > /dev/null || true; done
  else
    "$bin" all --scale quick --seed "$s" --threads "$threads" --quiet --out "$out/seed$s" > /dev/null || true
  fi
  echo "seed $s done" >&2
done
table=$(for ((s = 1; s <= n; s++)); do
  "$bin" check --all --missing-ok --out "$out/seed$s" 2> /dev/null || true
done | awk -v n="$n" '
  /^check / { ex = $2; next }
  !/^  / || /^  claim / || /^  \(/ || NF < 2 { next } # claim rows only: not the headline, totals or notes
  { v = $NF; if (v == "skipped") next; id = ex "/" $1; seen[id]++; count[id, v]++ }
  END {
    printf "%-52s %5s %9s %5s  (of %d seeds)\n", "claim", "PASS", "DEVIATION", "FAIL", n
    for (id in seen) printf "%d\t%-52s %5d %9d %5d\n", count[id, "PASS"] + count[id, "DEVIATION"], id,
                            count[id, "PASS"], count[id, "DEVIATION"], count[id, "FAIL"]
  }' | { IFS= read -r header; echo "$header"; sort -n -k1,1 | cut -f2-; })
echo "$table"
if ((strict)) && echo "$table" | awk 'NR > 1 && $NF > 0 { bad = 1 } END { exit !bad }'; then
  echo "seed_pass_rates: a claim judged at quick scale FAILs for some seed (last column above)" >&2
  exit 1
fi
