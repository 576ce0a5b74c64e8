#!/usr/bin/env bash
# Luding 1998 Sec. 3.1: "DSMC dissipates more energy than ED as soon as the number of central
# collisions is overestimated" (issue 27 §5): the mechanism, checked as the energy lost per
# collision of ED and DSMC in windows of t/t0, from the cooling experiment's K(t) and C/N(t):
#   loss per collision = -ln(K(b)/K(a)) / ((1 - r^2)/2 (C/N(b) - C/N(a)))
# in units of the molecular-chaos loss of a Maxwellian gas at the global temperature (1: Haff).
# No claim yet (needs a scalar of the driver); this prints the table.
#   scripts/studies/cooling_loss_per_collision.sh [RUN_DIR]   (default: runs
#   granrepro cooling --scale paper --threads 1 into out-studies/cooling-loss, ~15 min on a busy
#   2-core machine)
set -euo pipefail
cd "$(dirname "$0")/../.."
bin=${GRANREPRO:-./build/granrepro}
run=${1:-out-studies/cooling-loss}
if [ ! -f "$run/cooling/summary.json" ]; then
  rc=0
  "$bin" cooling --scale paper --threads 1 --quiet --out "$run" > /dev/null || rc=$?
  if [ "$rc" -gt 1 ]; then echo "granrepro cooling failed (exit $rc)" >&2; exit "$rc"; fi
fi
PYTHONPATH=python /usr/bin/python3 - "$run/cooling" <<'PY'
import sys
import numpy as np
import granrepro
r = granrepro.load(sys.argv[1])
rr = r.parameters["r"].value
t0 = 1 / r.value("t0_inv_kinetic_theory")
e, d = r.tables["energy_ed"], r.tables["energy_dsmc"]
def seg(tab, a, b):
    t, K, c = tab["t"] / t0, tab["K_over_K0"], tab["C_over_N"]
    Ka, Kb = np.interp([a, b], t, K)
    ca, cb = np.interp([a, b], t, c)
    return -np.log(Kb / Ka) / ((1 - rr * rr) / 2 * (cb - ca)), cb - ca
edges = [0.1, 0.5, 1, 2, 5, 10, 20, 50, 100, 200, 500, 900]
print("| t/t0 | ED loss per collision | ED C/N in window | DSMC loss per collision | DSMC C/N in window | DSMC/ED |")
print("|---|---|---|---|---|---|")
for a, b in zip(edges[:-1], edges[1:]):
    if b * t0 > min(e["t"][-1], d["t"][-1]): break
    le, ce = seg(e, a, b)
    ld, cd = seg(d, a, b)
    print(f"| {a:g}-{b:g} | {le:.3f} | {ce:.1f} | {ld:.3f} | {cd:.1f} | {ld / le:.2f} |")
PY
