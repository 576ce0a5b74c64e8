#!/usr/bin/env bash
# Issue 26: the fast start's speed against the fast branch at the decisive e_N (k_N = 2000 N/m,
# paper pipe, default wall and budget). The paper starts the fast branch at "high initial mean
# velocities of about 5-10 m/s" (text below Fig. 6); a start reaches the emergency-brake state only
# from inside its basin, which shrinks as e_N grows. Per fast_v0 one paper-scale run:
#   granrepro bistable-pipe --scale paper --set kN_list=2000 --set eN_list=$EN --set fast_v0=V
# and a table of each start's steady speed (m/s; "ff" free fall, "un" unsettled).
#   V_LIST='8 10 12 15' EN=0.9,0.925,0.95,0.99 scripts/studies/bistable_pipe_fast_v0.sh
# Runs go to $OUT/v<V> (default out-studies/bistable-pipe-fast-v0); a finished run is reused.
set -euo pipefail
cd "$(dirname "$0")/../.."
bin=${GRANREPRO:-./build/granrepro}
out=${OUT:-out-studies/bistable-pipe-fast-v0}
en=${EN:-0.9,0.925,0.95,0.99}
for v in ${V_LIST:-8 10 12 15}; do
  dir="$out/v$v"
  [ -f "$dir/bistable-pipe/summary.json" ] && continue
  "$bin" bistable-pipe --scale paper --set kN_list=2000 --set "eN_list=$en" --set "fast_v0=$v" \
    --threads "${THREADS:-1}" --quiet --out "$dir" > /dev/null || true
done
python3 - "$out" ${V_LIST:-8 10 12 15} <<'PY'
import csv, os, sys
out, vs = sys.argv[1], sys.argv[2:]
rows = {}
for v in vs:
    p = os.path.join(out, "v" + v, "bistable-pipe", "tables", "steady_k2000.tsv")
    if not os.path.exists(p):
        continue
    for r in csv.DictReader((l for l in open(p) if not l.startswith("#")), delimiter="\t"):
        e = float(r["e_N"])
        o = int(float(r["outcome_fast"]))
        cell = ("%.3g" % float(r["v_fast"])) if o == 0 else ("ff %.3g" % float(r["v_last_fast"]) if o == 1 else "un %.3g" % float(r["v_last_fast"]))
        slow = ("%.3g" % float(r["v_slow"])) if int(float(r["outcome_slow"])) == 0 else "not steady"
        rows.setdefault(e, {})[v] = cell
        rows[e]["slow"] = slow
print("| e_N | slow start |" + "".join(" fast start %s m/s |" % v for v in vs))
print("|---:|---:|" + "---:|" * len(vs))
for e in sorted(rows):
    print("| %.3g | %s |" % (e, rows[e].get("slow", "")) + "".join(" %s |" % rows[e].get(v, "not run") for v in vs))
PY
