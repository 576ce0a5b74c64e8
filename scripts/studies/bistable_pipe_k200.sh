#!/usr/bin/env bash
# Issue 26: does k_N = 200 N/m have the paper's short normal branch ("the normal branch still exists for
# nearly elastic grains, but it is so short that we do not plot it", text below Fig. 6) above the grid's
# largest e_N (0.99)? Runs the k_N = 200 row at e_N = 0.995 and 0.999, slow and fast starts, with the
# default run's settings (agitation scaled to 0.25 v_crit(200) = 0.32 m/s, 6 m hold, paper budget).
#
#   scripts/studies/bistable_pipe_k200.sh [quick|paper]     (OUT, GRANREPRO, THREADS, SEEDS as below)
# Prints per e_N and seed: each start's outcome (steady speed in m/s; "ff N" free fall, "un N" unsettled,
# N the last speed) and whether the slow start stays below v_crit(200) = 1.26 m/s (the normal regime).
set -euo pipefail
cd "$(dirname "$0")/../.."
scale=${1:-paper}
bin=${GRANREPRO:-./build/granrepro}
read -r -a seeds <<< "${SEEDS:-1}"
out=${OUT:-out-studies/bistable-pipe-k200-$scale}
dirs=()
for seed in "${seeds[@]}"; do
  dir="$out/seed$seed"
  dirs+=("$dir")
  [ -f "$dir/bistable-pipe/tables/steady_k200.tsv" ] && continue
  rc=0
  "$bin" bistable-pipe --scale "$scale" --seed "$seed" --threads "${THREADS:-2}" --quiet --set kN_list=200 \
    --set eN_list=0.995,0.999 --set length_check=0 --out "$dir" > /dev/null || rc=$?
  if ((rc > 1)); then echo "bistable_pipe_k200: run $dir failed (exit $rc)" >&2; exit "$rc"; fi
done
python3 - "${dirs[@]}" <<'PY'
import csv, sys
V_CRIT = 4.0 * (200 / 2000) ** 0.5
print("| seed | e_N | slow start | fast start | slow start in the normal regime |")
print("|---:|---:|---|---|---|")
for d in sys.argv[1:]:
    rows = csv.DictReader((l for l in open(d + "/bistable-pipe/tables/steady_k200.tsv") if not l.startswith("#")), delimiter="\t")
    for r in rows:
        cell = {}
        for s in ("slow", "fast"):
            o = int(float(r["outcome_" + s]))
            cell[s] = "%.2f" % float(r["v_" + s]) if o == 0 else "%s %.0f (t = %.1f s)" % ("ff" if o == 1 else "un", float(r["v_last_" + s]), float(r["t_end_" + s]))
        slow_ok = int(float(r["outcome_slow"])) == 0 and float(r["v_slow"]) < V_CRIT
        print("| %s | %s | %s | %s | %s |" % (d.rsplit("seed", 1)[1], r["e_N"], cell["slow"], cell["fast"], "yes" if slow_ok else "no"))
PY
