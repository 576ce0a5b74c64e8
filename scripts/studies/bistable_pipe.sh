#!/usr/bin/env bash
# Sensitivity studies of the bistable pipe (Schäfer & Wolf Fig. 6, issue 13), at quick scale and
# k_N = 2000 N/m, e_N = 0.7 and 0.95, slow and fast starts. Each row is one granrepro run; the
# table prints each start's outcome (steady speed, or "ff" free fall / "un" unsettled with the
# last speed, ">" when it passed v_abort) in m/s.
#   scripts/studies/bistable_pipe.sh readings     Eq. (2) readings x wall spacing (0.66, 1 mm)
#   scripts/studies/bistable_pipe.sh parameters   magnitude reading: wall spacing, agitation,
#                                                 polydispersity, pipe length
# Runs go to $OUT (default out-studies/bistable-pipe/); a finished row is reused when rerun.
set -euo pipefail
cd "$(dirname "$0")/../.."
bin=${GRANREPRO:-./build/granrepro}
out=${OUT:-out-studies/bistable-pipe}
budget=${BUDGET:-1e5}   # in t_col: 7.1 s at e_N = 0.7, enough for the e_N = 0.7 fast branch (~40 m/s)
common=(--set kN_list=2000 --set eN_list=0.7,0.95 --set budget_tcol="$budget" --threads "${THREADS:-2}" --quiet)

row() { # row NAME --set ... : runs one configuration and prints its line
  local name=$1; shift
  local dir="$out/$name"
  if [ ! -f "$dir/bistable-pipe/tables/steady_k2000.tsv" ]; then
    "$bin" bistable-pipe "${common[@]}" "$@" --out "$dir" > /dev/null || true
  fi
  python3 - "$dir/bistable-pipe/tables/steady_k2000.tsv" "$name" <<'PY'
import csv, math, sys
path, name = sys.argv[1], sys.argv[2]
rows = list(csv.DictReader((l for l in open(path) if not l.startswith("#")), delimiter="\t"))  # line 2: units
cells = []
for r in rows:
    for s in ("slow", "fast"):
        o = int(float(r["outcome_" + s]))
        if o == 0:
            cells.append("%.2f" % float(r["v_" + s]))
        else:
            cells.append("%s %.0f" % ("ff" if o == 1 else "un", float(r["v_last_" + s])))
print("| %-34s | %s |" % (name, " | ".join("%-9s" % c for c in cells)))
PY
}

header() {
  echo "| configuration                      | 0.7 slow  | 0.7 fast  | 0.95 slow | 0.95 fast |"
  echo "|------------------------------------|-----------|-----------|-----------|-----------|"
}

case "${1:-}" in
  readings)
    header
    for r in magnitude clipped elastic signed; do
      for sp in 0.66e-3 1e-3; do
        row "friction_normal=$r wall_spacing=$sp" --set "friction_normal=$r" --set "wall_spacing=$sp"
      done
    done ;;
  parameters)
    header
    for sp in 0.66e-3 0.8e-3 1e-3 1.32e-3; do row "wall_spacing=$sp" --set "wall_spacing=$sp"; done
    for a in 0.3 3; do row "agitation=$a" --set "agitation=$a"; done
    for pd in 0 0.2; do row "polydispersity=$pd" --set "polydispersity=$pd"; done
    row "length=0.04" --set length=0.04
    for v in 5 10; do row "fast_v0=$v" --set "fast_v0=$v"; done ;;
  *) echo "usage: $0 readings|parameters" >&2; exit 2 ;;
esac
