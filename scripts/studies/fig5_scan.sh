#!/usr/bin/env bash
# Luding (1998) Fig. 5 (issue 27 §1): which of the paper's Fig. 5 / Sec. 3.2 statements hold,
# against the two choices the paper leaves open for N = 240, rho = 0.7495: the TC cut-off t_c
# and the initial mean velocity vbar. Each cell is one paper-scale impact-parameter run (32 seeds
# of r = 0.80, 0.90, 0.95 to t = 1 s; the elastic and 3D checks shrunk to a token, they are not
# measured here), seed 1, --threads 1.
#   scripts/studies/fig5_scan.sh scan     t_c in {1e-6, 1e-5, 1e-4, 1e-3 s} x vbar in {0.05, 0.2047, 1 m/s}
#   scripts/studies/fig5_scan.sh rough    rough disks (mu, beta0) at T_C, VBAR (default: the scan's best cell)
# Output: scripts/studies/fig5_scan.md is these two tables (rerun both to regenerate it).
# Runs go to $OUT (default out-studies/fig5/); a finished cell is reused when rerun.
# Columns (fraction of the 32 seeds unless stated; S1-S14 are the statements counted in "held"):
#   S1 v8>v9>v95  seeds with v_rms(0.8) > v_rms(0.9) > v_rms(0.95) at 1 s (arrow factors 1, 3, 7)   >= 0.5
#   S2 eddies     seeds with a significant co-rotating eddy pair at r = 0.8                            >= 0.5
#   S3 s9 least   seeds with sigma_max(0.9) the smallest panel                                        >= 0.5
#   S4 s95 most   seeds with sigma_max(0.95) the largest panel                                        >= 0.5
#   S5 core p     median core/outside pressure of the strongest pair at r = 0.8                       < 1
#   S6 out aniso  median outside/core stress anisotropy at r = 0.8                                    > 1
#   S7,S8 rand9/95 seeds whose stress axes pass as random at r = 0.9 / 0.95                           >= 0.5
#   S9 Kf 0.8     K_flow/K at r = 0.8 (shear visible)                                                 >= 0.417
#   S10,S11 Kf 0.9/0.95 (no visible shear)                                                            < 0.417
#   S12 z 0.8     grazing-ratio z at r = 0.8 ("increasing probability of grazing contacts")          >= 3
#   S13,S14 R9/R95 grazing ratio at r = 0.9 / 0.95 within 3 single-run Poisson errors of 1 (flat_r0.9x)
#   flow/th 0.8   K_flow / (K - K_flow) at r = 0.8, mean over seeds
#   TC 0.8        fraction of r = 0.8 collisions made elastic by TC
#   v8/v9, v8/v95 geometric-mean speed ratios at 1 s (paper's arrow factors imply 3 and 7)
set -euo pipefail
cd "$(dirname "$0")/../.."
bin=${GRANREPRO:-./build/granrepro}
out=${OUT:-out-studies/fig5}
common=(impact-parameter --scale paper --seed 1 --threads 1 --quiet
        --set elastic_densities=0.05 --set elastic_collisions_per_particle=1
        --set elastic3d_packing=0.05 --set elastic3d_collisions=100)

row() { # row NAME --set ... : runs one cell (unless done) and prints its table line
  local name=$1; shift
  local dir="$out/$name"
  if [ ! -f "$dir/impact-parameter/summary.json" ]; then
    nice -n 10 "$bin" "${common[@]}" "$@" --out "$dir" > "$out/$name.log" 2>&1 || true
  fi
  /usr/bin/python3 - "$dir/impact-parameter/summary.json" "$name" <<'PY'
import json, math, os, sys
path, name = sys.argv[1], sys.argv[2]
if not os.path.exists(path):
    print("| %-28s | run failed (see its .log) |" % name)
    sys.exit(0)
s = {k: (v["value"] if isinstance(v, dict) else v) for k, v in json.load(open(path))["scalars"].items()}
g = lambda k: s.get(k, float("nan"))
seeds = 32
def flat(r):  # ratio within 3 single-run Poisson errors (pooled error x sqrt(seeds))
    return abs(g("grazing_ratio_r" + r) - 1) <= 3 * g("grazing_ratio_err_r" + r) * math.sqrt(seeds)
tests = [g("seeds_v_rms_order_080_090_095") >= 0.5, g("eddy_pair_fraction_r0.80") >= 0.5,
         g("seeds_sigma_max_090_lowest") >= 0.5, g("seeds_sigma_max_095_highest") >= 0.5,
         g("eddy_core_pressure_ratio_median_all_r0.80") < 1, g("eddy_outside_anisotropy_ratio_median_all_r0.80") > 1,
         g("stress_axes_random_fraction_r0.90") >= 0.5, g("stress_axes_random_fraction_r0.95") >= 0.5,
         g("flow_fraction_mean_r0.80") >= 0.417, g("flow_fraction_mean_r0.90") < 0.417, g("flow_fraction_mean_r0.95") < 0.417,
         g("grazing_z_r0.80") >= 3, flat("0.90"), flat("0.95")]
held = "".join("x" if t else "." for t in tests)
vals = [g("seeds_v_rms_order_080_090_095"), g("eddy_pair_fraction_r0.80"), g("seeds_sigma_max_090_lowest"),
        g("seeds_sigma_max_095_highest"), g("eddy_core_pressure_ratio_median_all_r0.80"),
        g("eddy_outside_anisotropy_ratio_median_all_r0.80"), g("stress_axes_random_fraction_r0.90"),
        g("stress_axes_random_fraction_r0.95"), g("flow_fraction_mean_r0.80"), g("flow_fraction_mean_r0.90"),
        g("flow_fraction_mean_r0.95"), g("grazing_z_r0.80"), g("grazing_ratio_r0.90"), g("grazing_ratio_r0.95"),
        g("flow_to_thermal_mean_r0.80"), g("tc_elastic_fraction_r0.80"),
        g("v_rms_ratio_080_over_090_geomean"), g("v_rms_ratio_080_over_095_geomean")]
print("| %-28s | %2d %s | %s |" % (name, sum(tests), held, " | ".join("%.3g" % v for v in vals)))
PY
}

header() {
  echo "| cell                         | held (S1..S14)    | S1 v8>v9>v95 | S2 eddies | S3 s9 least | S4 s95 most | S5 core p | S6 out aniso | S7 rand9 | S8 rand95 | S9 Kf 0.8 | S10 Kf 0.9 | S11 Kf 0.95 | S12 z 0.8 | S13 R9 | S14 R95 | flow/th 0.8 | TC 0.8 | v8/v9 | v8/v95 |"
  echo "|------------------------------|-------------------|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"
}

mkdir -p "$out"
case "${1:-}" in
  scan)
    header
    for vb in 0.05 0.2047 1; do
      for tc in 1e-6 1e-5 1e-4 1e-3; do
        row "t_c=$tc vbar=$vb" --set "t_c=$tc" --set "vbar=$vb"
      done
    done ;;
  rough)
    tc=${T_C:?set T_C and VBAR to the best cell of the scan table}
    vb=${VBAR:?set T_C and VBAR}
    header
    row "t_c=$tc vbar=$vb" --set "t_c=$tc" --set "vbar=$vb"
    for mb in "0.5 0.4" "0.5 0" "0.1 0.4"; do
      set -- $mb
      row "mu=$1 beta0=$2 t_c=$tc vbar=$vb" --set "t_c=$tc" --set "vbar=$vb" --set "mu=$1" --set "beta0=$2"
    done ;;
  *) echo "usage: $0 scan | T_C=.. VBAR=.. $0 rough" >&2; exit 2 ;;
esac
