#!/usr/bin/env bash
# C/N of the cluster-growth run against the paper's three numbers (Luding 1998 Sec. 4: C/N = 8 at
# 0.04 s, 39 at 0.64 s, 183 at 10.24 s; issue 16): which of the parameters the paper leaves open
# moves our C/N to its values? Each variant runs the cluster-growth experiment until C/N >= 200
# (t = 20.48 s), without the second TC rule. v̄ and r are also varied together (v*-r* variants), and
# the table ends with a joint fit: C/N at the three instants, linear in v̄ and r over the variants
# that change only these (default, vbar*, r*, v*-r*), solved in least squares of ln C/N for the
# paper's 8 / 39 / 183 (issue 27 §3).
#   scripts/studies/cn_shortfall.sh                  paper scale (about 1 min per variant on 2 cores)
#   SCALE=quick scripts/studies/cn_shortfall.sh      quick scale
# Runs go to $OUT (default out-studies/cn-shortfall/<variant>); reruns reuse finished runs.
set -euo pipefail
cd "$(dirname "$0")/../.."
scale=${SCALE:-paper}
out=${OUT:-out-studies/cn-shortfall}
threads=${THREADS:-2}
bin=${GRANREPRO:-./build/granrepro}
declare -A variants=(
  [default]=""
  [tc-both]="tc_both=true"
  [vbar+10%]="vbar=0.2252"
  [vbar+20%]="vbar=0.2456"
  [r0.83]="r=0.83"
  [r0.85]="r=0.85"
  [equil100]="equilibration=100"
  [random-start]="initial_positions=random"
  [tc1e-4]="t_c=1e-4"
  [rough]="mu=0.5"
  # v̄ and r together (issue 27: fit both).
  [v10-r0.83]="vbar=0.2252 r=0.83"
  [v20-r0.83]="vbar=0.2456 r=0.83"
  [v10-r0.85]="vbar=0.2252 r=0.85"
  [v20-r0.85]="vbar=0.2456 r=0.85"
  # The least-squares compromise of the joint fit for 8 / 39 / 183 (cn_shortfall.md, issue 43 §4):
  # run directly instead of read off the fit.
  [compromise]="vbar=0.2473 r=0.8195"
  # The run-to-run scatter: the default with other seeds.
  [seed2]="seed=2"
  [seed3]="seed=3"
)
order=(default seed2 seed3 tc-both vbar+10% vbar+20% r0.83 r0.85 v10-r0.83 v20-r0.83 v10-r0.85 v20-r0.85 compromise equil100 random-start tc1e-4 rough)
if (($#)); then order=("$@"); fi
for v in "${order[@]}"; do
  [ -n "${variants[$v]+x}" ] || { echo "unknown variant $v" >&2; exit 2; }
  dir="$out/$v"
  if [ ! -f "$dir/cluster-growth/summary.json" ]; then
    args=(--set cn_end=200 --set tc_compare_until=0)
    for s in ${variants[$v]}; do
      if [[ $s == seed=* ]]; then args+=(--seed "${s#seed=}"); else args+=(--set "$s"); fi
    done
    echo "== $v: granrepro cluster-growth --scale $scale ${args[*]}" >&2
    "$bin" cluster-growth --scale "$scale" --threads "$threads" --quiet --out "$dir" "${args[@]}" > /dev/null 2>&1 || true
  fi
done
"${PYTHON:-/usr/bin/python3}" - "$out" "${order[@]}" <<'PY'
import json, os, sys
out, names = sys.argv[1], sys.argv[2:]
paper = {"0.04": 8.0, "0.64": 39.0, "10.24": 183.0}
print("%-14s %8s %8s %8s   %7s %7s %7s   %9s %9s" % ("variant", "C/N@0.04", "@0.64", "@10.24", "/paper", "/paper", "/paper", "enskog", "elastic%"))
for n in names:
    f = os.path.join(out, n, "cluster-growth", "summary.json")
    if not os.path.exists(f):
        print("%-14s missing" % n); continue
    sc = json.load(open(f))["scalars"]
    c = [sc.get("C_over_N_at_%ss" % t) for t in ("0.04", "0.64", "10.24")]
    r = [(x / paper[t]) if x else float("nan") for x, t in zip(c, ("0.04", "0.64", "10.24"))]
    print("%-14s %8.2f %8.2f %8.2f   %7.3f %7.3f %7.3f   %9.3f %9.3f" % (n, *[x or float("nan") for x in c], *r,
          sc.get("omega_equilibration_over_enskog") or float("nan"), 100 * (sc.get("elastic_fraction_early_max") or float("nan"))))
# Joint fit of v̄ and r: ln C/N at each instant linear in (v̄, r) over the variants that change
# only these two, then the (v̄, r) that minimises the squared ln distance to the paper's values.
import numpy as np
rows = []
for n in names:
    f = os.path.join(out, n, "cluster-growth", "summary.json")
    if not os.path.exists(f): continue
    # the compromise is the fit's prediction, run to test it: not a point of the fit
    if not (n == "default" or n.startswith("vbar") or n.startswith("r0.") or n.startswith("v1") or n.startswith("v2")): continue
    js = json.load(open(f))
    sc = js["scalars"]
    par = {p["name"]: p["value"] for p in js.get("parameters", [])} if isinstance(js.get("parameters"), list) else js.get("parameters", {})
    def pv(k, d):
        v = par.get(k, d)
        return v["value"] if isinstance(v, dict) else v
    c = [sc.get("C_over_N_at_%ss" % t) for t in ("0.04", "0.64", "10.24")]
    if None in c: continue
    rows.append((float(pv("vbar", 0.2047)), float(pv("r", 0.8)), *map(float, c)))
if len(rows) >= 4:
    A = np.array([[1, v, r] for v, r, *_ in rows])
    Y = np.log(np.array([[c0, c1, c2] for _, _, c0, c1, c2 in rows]))
    coef, *_ = np.linalg.lstsq(A, Y, rcond=None)
    resid = Y - A @ coef
    print("\njoint fit over %d (v̄, r) variants: ln C/N = a + b v̄ + c r; rms residual of ln C/N per instant: %s" % (len(rows), " ".join("%.3f" % x for x in np.sqrt((resid ** 2).mean(axis=0)))))
    target = np.log([8.0, 39.0, 183.0])
    B = coef[1:].T  # 3 x 2
    x, *_ = np.linalg.lstsq(B, target - coef[0], rcond=None)
    pred = np.exp(coef[0] + B @ x)
    print("best (v̄, r) for 8 / 39 / 183 (all three): v̄ = %.4f m/s, r = %.4f -> C/N %.2f / %.2f / %.1f" % (x[0], x[1], *pred))
    for name, idx in (("0.64 s and 10.24 s", [1, 2]), ("0.04 s and 0.64 s", [0, 1])):
        x2 = np.linalg.solve(B[idx], target[idx] - coef[0][idx])
        p2 = np.exp(coef[0] + B @ x2)
        print("exact for %s: v̄ = %.4f m/s, r = %.4f -> C/N %.2f / %.2f / %.1f" % (name, x2[0], x2[1], *p2))
PY
