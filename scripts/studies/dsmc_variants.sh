#!/usr/bin/env bash
# DSMC variants against ED (Luding 1998 Secs. 2.4, 3.3; issue 16): one ED reference run of the
# cooling experiment (equilibration, ED and default DSMC for each seed), then every variant as
# DSMC alone from the same equilibrated states (run_ed=false); the table lists, per variant, what
# the claims in expected/cooling.toml look at. The study behind Sk_ed_dsmc_agree.
#   scripts/studies/dsmc_variants.sh                 paper scale, 3 seeds (ED reference ~3 CPU-min, then 0.5-3
#                                                    CPU-min per variant; 2 d cells are the slow ones)
#   SCALE=quick scripts/studies/dsmc_variants.sh     quick scale
#   scripts/studies/dsmc_variants.sh nearest paper   only these variants
# Runs go to $OUT (default out-studies/dsmc-variants/<variant>); reruns reuse finished runs.
set -euo pipefail
cd "$(dirname "$0")/../.."
scale=${SCALE:-paper}
out=${OUT:-out-studies/dsmc-variants}
threads=${THREADS:-2}
bin=${GRANREPRO:-./build/granrepro}
declare -A variants=(
  # Sec. 2.4 as printed: cells max(lambda/2, 2 d), V_c - V_0 from the cell's own disks, offset d.
  [paper]="dsmc_cell_diameters=2 dsmc_free_volume=cell dsmc_free_volume_block=1 dsmc_displacement=true dsmc_partner=uniform dsmc_no_repeat=false dsmc_mft_fraction=0"
  # The same with V_0 from the mean density (the free-volume factor of the box, 1/(1 - rho/0.82)).
  [paper-mean]="dsmc_cell_diameters=2 dsmc_free_volume=mean dsmc_displacement=true dsmc_partner=uniform dsmc_no_repeat=false dsmc_mft_fraction=0"
  # The former default: 10 d cells chosen to match Fig. 2's energy curve.
  [cells10]="dsmc_cell_diameters=10 dsmc_free_volume=mean dsmc_displacement=true dsmc_partner=uniform dsmc_no_repeat=false dsmc_mft_fraction=0"
  # Remedies on the paper's cells, one by one and together.
  [norepeat]="dsmc_cell_diameters=2 dsmc_free_volume=mean dsmc_displacement=true dsmc_partner=uniform dsmc_no_repeat=true dsmc_mft_fraction=0"
  [nearest]="dsmc_cell_diameters=2 dsmc_free_volume=mean dsmc_displacement=true dsmc_partner=nearest dsmc_no_repeat=true dsmc_mft_fraction=0"
  [nearest-step]="dsmc_cell_diameters=2 dsmc_free_volume=mean dsmc_displacement=true dsmc_partner=nearest dsmc_no_repeat=true dsmc_mft_fraction=0.05"
  [nearest-block3]="dsmc_cell_diameters=2 dsmc_free_volume=cell dsmc_free_volume_block=3 dsmc_displacement=true dsmc_partner=nearest dsmc_no_repeat=true dsmc_mft_fraction=0"
  [nearest-cells10]="dsmc_cell_diameters=10 dsmc_free_volume=mean dsmc_displacement=true dsmc_partner=nearest dsmc_no_repeat=true dsmc_mft_fraction=0"
  # Per-cell free volume (the paper's wording) in cells large enough to estimate the local density.
  [cells5-cell]="dsmc_cell_diameters=5 dsmc_free_volume=cell dsmc_free_volume_block=1 dsmc_displacement=true dsmc_partner=uniform dsmc_no_repeat=false dsmc_mft_fraction=0"
  [cells10-cell]="dsmc_cell_diameters=10 dsmc_free_volume=cell dsmc_free_volume_block=1 dsmc_displacement=true dsmc_partner=uniform dsmc_no_repeat=false dsmc_mft_fraction=0"
  [cells10-cell-norepeat]="dsmc_cell_diameters=10 dsmc_free_volume=cell dsmc_free_volume_block=1 dsmc_displacement=true dsmc_partner=uniform dsmc_no_repeat=true dsmc_mft_fraction=0"
  # The default with the free-volume factor set to Henderson's g(d) = 1.5833 (rho/(1 - s_*) = 0.6786
  # instead of 0.82): DSMC at the Enskog rate, ED's (issue 43 §3; scripts/studies/cooling_dsmc_rate.sh).
  [cells10-enskog]="dsmc_cell_diameters=10 dsmc_free_volume=mean dsmc_rcp_fraction=0.6786 dsmc_displacement=true dsmc_partner=uniform dsmc_no_repeat=false dsmc_mft_fraction=0"
  # Without the dense-gas corrections (a dilute Boltzmann gas at rho = 0.25).
  [plain-nearest]="dsmc_cell_diameters=2 dsmc_free_volume=off dsmc_displacement=false dsmc_partner=nearest dsmc_no_repeat=true dsmc_mft_fraction=0"
)
order=(paper paper-mean cells10 cells10-enskog norepeat nearest nearest-step nearest-block3 nearest-cells10 cells5-cell cells10-cell cells10-cell-norepeat plain-nearest)
if (($#)); then order=("$@"); fi
seeds=${SEEDS:-3}
# A cooling run whose claims may fail (exit 1: DSMC variants are meant to depart) but which must
# have written its results; with run_ed=false the figures, which need the ED tables, are not
# drawn (exit 4).
run_cooling() {
  local rc=0
  "$bin" cooling --scale "$scale" --threads "$threads" --quiet "$@" > /dev/null || rc=$?
  if [ "$rc" -gt 1 ] && [ "$rc" -ne 4 ]; then echo "granrepro cooling $* failed (exit $rc)" >&2; exit "$rc"; fi
}

# One ED reference run (with the default DSMC), then every variant as DSMC alone from the same
# initial states (run_ed=false): the ED runs are the same for every variant.
if [ ! -f "$out/reference/cooling/summary.json" ]; then
  echo "== reference: granrepro cooling --scale $scale --set seeds=$seeds" >&2
  run_cooling --out "$out/reference" --set seeds="$seeds"
fi
for v in "${order[@]}"; do
  [ -n "${variants[$v]+x}" ] || { echo "unknown variant $v (known: ${!variants[*]})" >&2; exit 2; }
  dir="$out/$v"
  if [ ! -f "$dir/cooling/summary.json" ]; then
    args=(--set seeds="$seeds" --set run_ed=false)
    for s in ${variants[$v]}; do args+=(--set "$s"); done
    echo "== $v: granrepro cooling --scale $scale ${args[*]}" >&2
    run_cooling --out "$dir" "${args[@]}"
  fi
done
python3 - "$out" "${order[@]}" <<'PY'
# Per variant: S(k) of DSMC against ED (mean over 1 <= k <= 25 of ln(S_DSMC/S_ED), per seed, at
# 20 s and at the last snapshot), DSMC's own change from 20 s on, the cell imprint, K_DSMC/K_ED,
# and what the variant does before clustering against kinetic theory.
import json, math, os, sys
out, names = sys.argv[1], sys.argv[2:]

def table(path):
    rows = [l.rstrip("\n").split("\t") for l in open(path) if not l.startswith("#")]  # line 2: units
    head = rows[0]
    return {h: [float(r[i]) if r[i] not in ("", "NaN", "nan") else float("nan") for r in rows[1:]] for i, h in enumerate(head)}

def mean_sd(v):
    m = sum(v) / len(v)
    return m, (math.sqrt(sum((x - m) ** 2 for x in v) / (len(v) - 1)) if len(v) > 1 else float("nan"))

def mean_over(S, k, lo, hi):
    v = [s for s, kk in zip(S, k) if lo <= kk <= hi]
    return sum(v) / len(v) if v else float("nan")

def log_ratio(a, b, k, kmax=25):
    v = [math.log(x / y) for x, y, kk in zip(a, b, k) if 1 <= kk <= kmax and x > 0 and y > 0]
    return sum(v) / len(v)

def interp_log(t, y, tq):
    for i in range(1, len(t)):
        if t[i] >= tq and t[i - 1] > 0:
            f = math.log(tq / t[i - 1]) / math.log(t[i] / t[i - 1])
            return y[i - 1] + f * (y[i] - y[i - 1])
    return float("nan")

def first_exceeding(x, y, level):
    for i in range(1, len(x)):
        if abs(y[i]) > level >= abs(y[i - 1]) and x[i - 1] > 0:
            f = (level - abs(y[i - 1])) / (abs(y[i]) - abs(y[i - 1]))
            return math.exp(math.log(x[i - 1]) + f * math.log(x[i] / x[i - 1]))
    return float("nan")

ref = os.path.join(out, "reference", "cooling")
refsum = json.load(open(os.path.join(ref, "summary.json")))
par = {k: v.get("value", v) if isinstance(v, dict) else v for k, v in refsum["parameters"].items()}
seeds = int(refsum["scalars"]["seeds"])
rho, d, n = 0.25, 1e-3, int(par.get("n_side", 316)) ** 2 if not isinstance(par.get("n_side"), dict) else 0
t0 = 1.0 / refsum["scalars"]["t0_inv_kinetic_theory"]
L = refsum["scalars"]["box"]
print("reference: %s (ED, %d seeds); t0 = %.4f s" % (ref, seeds, t0))
cols = ["variant", "S_D/S_E@40s", "ln+-sd", "S_D/S_E@20s", "ln+-sd", "dS_D 20->40", "imprint", "rate/En", "t0fit", "K/K18@2t0",
        "KD/KE@5t0", "split t/t0", "a2 (+-)", "wall s"]
print("\t".join(cols))
for name in names:
    vdir = os.path.join(out, name, "cooling")
    if not os.path.exists(os.path.join(vdir, "summary.json")):
        print(name + "\tmissing"); continue
    vs = json.load(open(os.path.join(vdir, "summary.json")))
    sc = vs["scalars"]
    vp = vs["parameters"]
    m40, m20, ch, imp, kk5, split = [], [], [], [], [], []
    for s in range(seeds):
        E = table(os.path.join(ref, "tables", "sk_ed_seed%d.tsv" % s))
        D = table(os.path.join(vdir, "tables", "sk_dsmc_seed%d.tsv" % s))
        k = E["k"]
        last = [c for c in E if c.startswith("S_t")][-1]
        m40.append(log_ratio(D[last], E[last], k))
        if "S_t20" in E:
            m20.append(log_ratio(D["S_t20"], E["S_t20"], k))
            ch.append(mean_over(D[last], k, 1, 25) / mean_over(D["S_t20"], k, 1, 25) - 1)
        # cell imprint: cells per side from Sec. 2.4's rule with this variant's settings
        cd = float(vp["dsmc_cell_diameters"]["value"] if isinstance(vp["dsmc_cell_diameters"], dict) else vp["dsmc_cell_diameters"])
        fv = vp["dsmc_free_volume"]["value"] if isinstance(vp["dsmc_free_volume"], dict) else vp["dsmc_free_volume"]
        nn = 4 * rho / (math.pi * d * d)
        chi = 1.0 if fv == "off" else 1.0 / (1 - rho / 0.82)
        lam = 1.0 / (math.sqrt(2) * nn * 2 * d * chi)
        cells = max(1, math.floor(L / max(lam / 2, cd * d)))
        M = 2 * k[-1]
        kc = abs(cells - M * round(cells / M))
        def bump(S):
            c = mean_over(S, k, kc - 2, kc + 2); lo = mean_over(S, k, 0.75 * kc - 2, 0.75 * kc + 2)
            hi = mean_over(S, k, 1.25 * kc - 2, 1.25 * kc + 2) if 1.25 * kc + 2 <= k[-1] else float("nan")
            return c / math.sqrt(lo * hi) if hi == hi else c / lo
        imp.append(bump(D[last]) / bump(E[last]))
        Ee = table(os.path.join(ref, "tables", "energy_ed_seed%d.tsv" % s))
        De = table(os.path.join(vdir, "tables", "energy_dsmc_seed%d.tsv" % s))
        kk5.append(interp_log(De["t"], De["K_over_K0"], 5 * t0) / interp_log(Ee["t"], Ee["K_over_K0"], 5 * t0))
        x = [t / t0 for t in Ee["t"]]
        y = [b / a - 1 for a, b in zip(Ee["K_over_K0"], De["K_over_K0"])]
        split.append(first_exceeding(x, y, 0.1))
    f = lambda v, fmt: (fmt % v) if v == v else "-"
    a, b = mean_sd(m40)
    row = [name, f(math.exp(a), "%.2f"), "%+.2f+-%.2f" % (a, b)]
    if m20:
        a2_, b2_ = mean_sd(m20)
        row += [f(math.exp(a2_), "%.2f"), "%+.2f+-%.2f" % (a2_, b2_), "%+.2f+-%.2f" % mean_sd(ch)]
    else:
        row += ["-", "-", "-"]
    row += [f(mean_sd(imp)[0], "%.2f"), f(sc.get("dsmc_rate_over_enskog_early") or float("nan"), "%.3f"),
            f(sc.get("t0_fit_over_kinetic_dsmc") or float("nan"), "%.3f"), f(sc.get("dsmc_over_eq18_2t0") or float("nan"), "%.3f"),
            f(mean_sd(kk5)[0], "%.3f"), f(mean_sd(split)[0], "%.1f"),
            "%+.4f+-%.4f" % (sc.get("a2_hcs_dsmc") or float("nan"), sc.get("a2_hcs_err_dsmc") or float("nan")),
            f(sc.get("wall_time_dsmc") or float("nan"), "%.0f")]
    print("\t".join(row))
rs = refsum["scalars"]
g = lambda k: rs.get(k) if rs.get(k) is not None else float("nan")
print("ED (reference runs): rate/Enskog %.3f, t0 fit %.3f, K/K18@2t0 -, a2 %+.4f+-%.4f (van Noije-Ernst %+.4f), "
      "ln S(k<=25) seed sd %.3f, S_ED change 20->40 s %+.2f+-%.2f"
      % (g("ed_rate_over_enskog_early"), g("t0_fit_over_kinetic_ed"), g("a2_hcs_ed"), g("a2_hcs_err_ed"), g("a2_van_noije_ernst"),
         g("ed_Sk_log_seed_sd"), g("ed_Sk_change_after_20s"), g("ed_Sk_change_after_20s_sd")))
PY
