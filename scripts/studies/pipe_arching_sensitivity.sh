#!/usr/bin/env bash
# Sensitivity study of pipe-arching (Luding 1998 Sec. 5, issue 15): what the paper leaves open,
# varied one at a time around the defaults of experiments/pipe-arching.toml, and what it does to
# the wall load, the plug's braking, the opening below it, cracks, A, B and the first-arch time.
#
#   scripts/studies/pipe_arching_sensitivity.sh [GROUP...]     groups: tc wall start scale size (default: all)
#
# Environment: GRANREPRO (default ./build/granrepro), SEEDS (seeds per row, default 8),
# SCALE (default quick), OUT (default out/studies/pipe-arching), THREADS (default 1).
# Every row is one run `granrepro pipe-arching --scale $SCALE --set n_seeds=$SEEDS --set ...`,
# kept in $OUT/<row>/; rerunning reuses finished rows (delete a row's folder to redo it).
# Prints one tab-separated table: medians over seeds unless named otherwise (A, B, B/A: median
# over seeds with the standard error of the mean over seeds; gaps in diameters). The table it
# printed for the defaults of the commit that added it is pipe_arching_sensitivity.tsv here
# (quick scale, 8 seeds, 1 thread; deterministic, so a rerun prints the same numbers).
set -euo pipefail
GRANREPRO=${GRANREPRO:-./build/granrepro}
SEEDS=${SEEDS:-8}
SCALE=${SCALE:-quick}
OUT=${OUT:-out/studies/pipe-arching}
THREADS=${THREADS:-1}
mkdir -p "$OUT"
groups=("$@")
((${#groups[@]})) || groups=(tc wall start scale size)

# label | --set assignments (space separated)
rows_tc=(
  "default|"
  "t_c=1e-7|t_c=1e-7"
  "t_c=3e-7|t_c=3e-7"
  "t_c=3e-6|t_c=3e-6"
  "t_c=1e-5|t_c=1e-5"
  "tc_rule=both|tc_rule=both"
  "tc_friction=drop|tc_friction=drop"
  "drop,t_c=1e-7|tc_friction=drop t_c=1e-7"
  "drop,t_c=1e-5|tc_friction=drop t_c=1e-5"
  "drop,both|tc_friction=drop tc_rule=both"
)
rows_wall=(
  "epsilon_w=0.5|epsilon_w=0.5"
  "epsilon_w=1|epsilon_w=1"
  "mu_w=0.2|mu_w=0.2"
  "mu_w=1|mu_w=1"
  "beta0_w=-1|beta0_w=-1"
  "beta0_w=0.6|beta0_w=0.6"
  "q=0.5|q=0.5"
)
rows_start=(
  "v0=0.005|v0=0.005"
  "v0=0.05|v0=0.05"
  "t_relax=0.1|t_relax=0.1"
  "t_relax=0.4|t_relax=0.4"
)
rows_scale=(
  "d=0.5mm|d=0.5e-3"
  "d=2mm|d=2e-3"
  "g=4.9|g=4.905"
  "g=9.81|g=9.81"
  "g=14|g=14.0"
)
rows_size=(
  "L=10.1,N=781|width=10.1 n_particles=781"
  "L=40.4,N=3124|width=40.4 n_particles=3124"
  "L=20.2,N=781|n_particles=781"
  "L=20.2,N=3124|n_particles=3124"
)

# get SCALAR SUMMARY, fmt VALUE FORMAT
source "$(dirname "$0")/summary_fields.sh"

cols=(row wall_share wall_peak plug_wall brake_m/s open_below_d gap_after_d gap_any_d crack_frac arch_frac
      t_arch_s A_1/s A_sem B_1/s B_sem B/A B/A_sem B_t0.055 B_t0.065 arch_left_4ms react_lag_s above+below wall_slow_z s/seed)
(IFS=$'\t'; echo "${cols[*]}")
for grp in "${groups[@]}"; do
  declare -n rows="rows_$grp"
  for r in "${rows[@]}"; do
    label=${r%%|*}
    sets=()
    for a in ${r#*|}; do sets+=(--set "$a"); done
    dir="$OUT/$(echo "$label" | tr ',=' '_-')"
    s="$dir/pipe-arching/summary.json"
    if [[ ! -f $s ]]; then
      "$GRANREPRO" pipe-arching --scale "$SCALE" --threads "$THREADS" --quiet --out "$dir" \
        --set n_seeds="$SEEDS" "${sets[@]}" > "$dir.log" 2>&1 || true
    fi
    if [[ ! -f $s ]]; then echo -e "$label\t(run failed, see $dir.log)"; continue; fi
    line=("$label"
      "$(fmt "$(get wall_friction_share "$s")" %.3f)" "$(fmt "$(get wall_load_peak_median "$s")" %.2f)"
      "$(fmt "$(get plug_wall_load_median "$s")" %.2f)" "$(fmt "$(get arch_brake_median "$s")" %.3f)"
      "$(fmt "$(get opening_below_median "$s")" %.2f)" "$(fmt "$(get opening_max_after_median "$s")" %.3f)"
      "$(fmt "$(get opening_max_all_median "$s")" %.3f)" "$(fmt "$(get crack_fraction "$s")" %.2f)"
      "$(fmt "$(get arch_fraction "$s")" %.2f)" "$(fmt "$(get t_arch_median "$s")" %.3f)"
      "$(fmt "$(get A_fit_median_seeds "$s")" %.0f)" "$(fmt "$(get A_fit_seed_sem "$s")" %.0f)"
      "$(fmt "$(get B_fit_median_seeds "$s")" %.0f)" "$(fmt "$(get B_fit_seed_sem "$s")" %.0f)"
      "$(fmt "$(get B_over_A_median_seeds "$s")" %.2f)" "$(fmt "$(get B_over_A_seed_sem "$s")" %.2f)"
      "$(fmt "$(get B_t0.055_median_seeds "$s")" %.0f)" "$(fmt "$(get B_t0.065_median_seeds "$s")" %.0f)"
      "$(fmt "$(get arch_left_4ms_median "$s")" %.2f)" "$(fmt "$(get react_lag_median "$s")" %.3f)"
      "$(fmt "$(get arch_above_and_below_fraction "$s")" %.2f)" "$(fmt "$(get wall_slowdown_gain_z "$s")" %.1f)"
      "$(fmt "$(get seconds_per_seed_median "$s")" %.1f)")
    (IFS=$'\t'; echo "${line[*]}")
  done
done
