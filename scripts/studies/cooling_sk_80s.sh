#!/usr/bin/env bash
# The freely cooling gas run on to 80 s over 5 seeds at paper scale (issue 43 §3): the decisive run
# of Sk_stationary_after_20s and Sk_dsmc_stationary_after_20s (is S(1 <= k <= 25) stationary for
# t >= 20 s, each seed's change per 20 s, seed mean +- sd: expected/README.md rule 'average'), of
# g_early_elastic (its chi^2 per bin beyond contact over 5 seeds instead of one), of
# departure_from_hcs_at_2t0 (the first 10 % departure of K from Eq. (18) with each seed's own
# fitted t0 beside kinetic theory's), and of pbd_flat_early at paper scale (the grazing ratio over
# [0, t) from finer early P(b/d) windows). One run:
#   granrepro cooling --scale paper --threads 1 --set seeds=5 --set t_end=80
#     --set snapshot_times=0,0.05,0.5,2,5,10,20,40,60,80
#     --set bd_windows=0,0.005,0.01,0.02,0.05,0.1,0.5,2,5,20,40,80
# about 10 CPU-min (ED + DSMC, N = 99856). Its claims at 40 s are not judged by this run (the
# last snapshot is 80 s); the tables below are computed from its per-seed outcomes (data.h5
# /points), by the definitions of experiments/cooling/report_*.cpp (the scalars
# ed_departure_from_fit_t_over_t0, ed_g_early_vs_elastic_chi2_beyond_contact_mean and the tables
# sk_change_intervals, impact_parameter_grazing_from_t0 compute the same in the experiment).
#   scripts/studies/cooling_sk_80s.sh          run (if $OUT has no result) and print the tables
# The run goes to $OUT (default out-studies/cooling-80s).
set -euo pipefail
cd "$(dirname "$0")/../.."
out=${OUT:-out-studies/cooling-80s}
bin=${GRANREPRO:-./build/granrepro}
if [ ! -f "$out/cooling/summary.json" ]; then
  rc=0
  nice -n 10 "$bin" cooling --scale paper --threads 1 --quiet --out "$out" --set seeds=5 --set t_end=80 \
    --set snapshot_times=0,0.05,0.5,2,5,10,20,40,60,80 \
    --set bd_windows=0,0.005,0.01,0.02,0.05,0.1,0.5,2,5,20,40,80 > /dev/null || rc=$?
  # exit 1: claims judged at the last snapshot (80 s here, not 40 s) may fail; results are written.
  if [ "$rc" -gt 1 ]; then echo "granrepro cooling failed (exit $rc)" >&2; exit "$rc"; fi
fi
/usr/bin/python3 - "$out/cooling" <<'PY'
import json, math, sys
import h5py
import numpy as np
d = sys.argv[1]
summ = json.load(open(f"{d}/summary.json"))
sc = summ["scalars"]
t0 = 1 / sc["t0_inv_kinetic_theory"]
with h5py.File(f"{d}/data.h5", "r") as f:
    recs = json.loads(bytes(f["points/records"][()]))
recs.sort(key=lambda r: r["point"])
n = len(recs) // 2
eds = [r["outcome"] for r in recs[:n]]
dss = [r["outcome"] for r in recs[n:]]
snaps = [0, 0.05, 0.5, 2, 5, 10, 20, 40, 60, 80]
def ms(x):
    x = np.asarray(x, float)
    return x.mean(), x.std(ddof=1), x.std(ddof=1) / math.sqrt(len(x))
def small_k(tr, i):
    k = np.asarray(tr["S_k"]); S = np.asarray(tr["snapshots"][i]["S"])
    return S[(k >= 1) & (k <= 25)].mean()
print(f"run: {d}, {n} seeds, N = {int(sc['N'])}, code {summ.get('code_version')}")

# 1. S(1 <= k <= 25): change per 20 s interval, per seed, and the change of the seed mean.
print("\n## S(1 <= k <= 25): relative change per interval (per seed; seed mean ± sd, ± se; change of the seed-mean S)")
print("| method | interval | " + " | ".join(f"seed {k}" for k in range(n)) + " | mean | sd | se | of seed mean |")
print("|---|---|" + "---|" * (n + 4))
for name, trs in (("ED", eds), ("DSMC", dss)):
    for a, b in ((6, 7), (7, 8), (8, 9), (6, 9)):
        ch = [small_k(tr, b) / small_k(tr, a) - 1 for tr in trs]
        m, s, se = ms(ch)
        om = sum(small_k(tr, b) for tr in trs) / sum(small_k(tr, a) for tr in trs) - 1
        print(f"| {name} | {snaps[a]}-{snaps[b]} s | " + " | ".join(f"{x:+.3f}" for x in ch) + f" | {m:+.3f} | {s:.3f} | {se:.3f} | {om:+.3f} |")
# S_DSMC / S_ED at 20 and 40 s per seed (claim Sk_ed_dsmc_agree's measure).
print("\n## mean over 1 <= k <= 25 of ln(S_DSMC/S_ED) per seed")
for i in (6, 7, 9):
    v = []
    for e, s in zip(eds, dss):
        k = np.asarray(e["S_k"]); m = (k >= 1) & (k <= 25)
        v.append(np.mean(np.log(np.asarray(s["snapshots"][i]["S"])[m] / np.asarray(e["snapshots"][i]["S"])[m])))
    m_, s_, se = ms(v)
    print(f"t = {snaps[i]} s: " + ", ".join(f"{x:+.3f}" for x in v) + f"; mean {m_:+.3f} sd {s_:.3f} (factor {math.exp(m_):.2f})")

# 2. Departure from Eq. (18): with kinetic theory's t0 and with each seed's own t0 fitted over t <= t0.
def first_departure(t, k, ref, level=0.1):
    x = t / t0; y = np.abs(k / ref - 1)
    for i in range(1, len(x)):
        if y[i] > level and y[i - 1] <= level and x[i - 1] > 0:
            f = (level - y[i - 1]) / (y[i] - y[i - 1])
            return math.exp(math.log(x[i - 1]) + f * math.log(x[i] / x[i - 1]))
    return float("nan")
print("\n## first t/t0 (kinetic t0) with |K/K_18 - 1| > 0.1, ED")
dep, dep_fit, fits = [], [], []
for tr in eds:
    t = np.asarray(tr["t"]); K = (np.asarray(tr["kx"]) + np.asarray(tr["ky"]) + np.asarray(tr["krot"]))
    K = K / K[0]
    m = (t > 0) & (t <= t0)
    y = 1 / np.sqrt(K[m]) - 1
    inv = float(np.sum(y * t[m]) / np.sum(t[m] ** 2))
    fits.append(inv * t0)
    dep.append(first_departure(t, K, 1 / (1 + t / t0) ** 2))
    dep_fit.append(first_departure(t, K, 1 / (1 + t * inv) ** 2))
for lab, v in (("fitted 1/t0 over kinetic", fits), ("departure, kinetic t0", dep), ("departure, own fitted t0", dep_fit)):
    m_, s_, se = ms(v)
    print(f"{lab}: " + ", ".join(f"{x:.3f}" for x in v) + f"; mean {m_:.3f} sd {s_:.3f} se {se:.3f}")

# 3. g(r/d) at 0.05 s against t = 0: chi^2 per bin over 1.1 <= r/d <= 5 (and from 0.98), per seed.
print("\n## g(r/d) at 0.05 s against t = 0, chi^2 per bin, ED")
for lo in (1.1, 0.98):
    v = []
    for tr in eds:
        r = np.asarray(tr["g_r"]); a, b = tr["snapshots"][0], tr["snapshots"][1]
        ga, gb = np.asarray(a["g"]), np.asarray(b["g"])
        var = np.asarray(a["g_err"]) ** 2 + np.asarray(b["g_err"]) ** 2
        m = (r >= lo) & (var > 0)
        v.append(float(np.mean((gb[m] - ga[m]) ** 2 / var[m])))
    m_, s_, se = ms(v)
    print(f"r/d >= {lo}: " + ", ".join(f"{x:.3f}" for x in v) + f"; mean {m_:.3f} sd {s_:.3f} se {se:.3f}")
# Where the excess lies: g(0.05 s) - g(0) in ranges of r/d, seed mean.
for lo, hi in ((1.0, 1.1), (1.1, 1.3), (1.3, 1.6), (1.6, 5.0)):
    v = []
    for tr in eds:
        r = np.asarray(tr["g_r"]); m = (r >= lo) & (r < hi)
        v.append(float(np.mean(np.asarray(tr["snapshots"][1]["g"])[m] - np.asarray(tr["snapshots"][0]["g"])[m])))
    m_, s_, se = ms(v)
    print(f"g(0.05 s) - g(0) over {lo}-{hi} d: mean {m_:+.4f} ± {se:.4f} (seeds " + ", ".join(f"{x:+.3f}" for x in v) + ")")

# 4. P(b/d): grazing ratio over [0, t) from the summed window counts, ED.
edges = [0, 0.005, 0.01, 0.02, 0.05, 0.1, 0.5, 2, 5, 20, 40, 80]
print("\n## grazing ratio P(b/d>0.8)/P(b/d<0.2) over [0, t), ED (20 bins of b/d)")
nb = len(eds[0]["impact_parameter"][0]["bins"])
centres = (np.arange(nb) + 0.5) / nb
hi, lo = (centres >= 0.8), (centres <= 0.2)
rows = []
for tr in eds:
    c = np.cumsum(np.array([w["bins"] for w in tr["impact_parameter"]], float), axis=0)
    rows.append(c[:, hi].mean(axis=1) / c[:, lo].mean(axis=1))
a = np.array(rows)
print("| t [s] | t/t0 | " + " | ".join(f"seed {k}" for k in range(n)) + " | mean ± se |")
print("|---|---|" + "---|" * (n + 1))
for j, t in enumerate(edges[1:]):
    m_, s_, se = ms(a[:, j])
    print(f"| {t:g} | {t / t0:.3g} | " + " | ".join(f"{x:.4f}" for x in a[:, j]) + f" | {m_:.4f} ± {se:.4f} |")
PY
