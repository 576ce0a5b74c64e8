#!/usr/bin/env bash
# Issue 27 §2 (Luding 1998 Sec. 5, the falling pile): the decisive TC thresholds at Earth's g.
# Fig. 13's white level N_c = 1e4 1/s is 1/t_c at t_c = 1e-4 s, where TC turns exactly the arch's
# collisions elastic; the earlier study (pipe_arching_sensitivity.sh) stopped at 1e-5 s. Here
# t_c = 3e-5, 1e-4, 3e-4 s, with friction kept and dropped in TC-elastic collisions, all at
# g = 9.81 m/s^2 and d = 1 mm (neither tuned: v̄ at t = 0 is an outcome), plus the reference row
# t_c = 1e-6 s (the default), friction kept, at g = 9.81 m/s^2. Then, since no TC row opens a crack
# or makes the arch vanish, the rough-wall rows: in the paper's model a wall's roughness is its
# tangential restitution (Eq. 6: beta0_w = -1 smooth, +1 perfectly rough) and its friction mu_w;
# beta0_w = 1 (the roughest wall the model has) at t_c = 1e-6 and 1e-4 s, and with mu_w = 0.7
# (mu_w = 1 jams the column at 0.019 s, pipe_arching_sensitivity.sh).
#
#   scripts/studies/pipe_arching_tc.sh
#
# Environment: GRANREPRO (default ./build/granrepro), SEEDS (seeds per row, default 32),
# REF_SEEDS (seeds of the reference row, default 32), SCALE (default paper: t_relax = 0.3 s),
# OUT (default out/studies/pipe-arching-tc), THREADS (default 1).
# Every row is one run `granrepro pipe-arching --scale $SCALE --set n_seeds=$SEEDS --set g=9.81
# --set ...`, kept in $OUT/<row>/; rerunning reuses finished rows. Deterministic: a rerun prints
# the same numbers. Prints one tab-separated table (pipe_arching_tc.tsv here is its output):
#   gap_*: the widest wall-to-wall gap [d] (crack detector; visible crack = 0.5 d) at any frame
#     from 0.01 s on (all) and within 10 ms after the first arch (after): median, quartiles, largest
#     over seeds; crack_frac: seeds with a visible crack; crack_by_0.060: seeds with one by 0.060 s
#     (claim crack_visible: in [0.1, 0.9]);
#   arch_left_4ms: share of the first arch's disks still at N_c >= 1e4 1/s 4 ms after it spanned
#     the width, median (the arch's lifetime; claim arch_almost_disappears: <= 0.25);
#   open_below: plug separation [d], median (claim plug_separates: >= 0.5 d);
#   t_arch: first arch, median and quartiles [s]; arch_by_0.056: claim arch_time_percentile
#     (in [0.1, 0.9]); arch_by_0.05: seeds with an arch by the last Fig. 14(a) time;
#   waves_up: share of steps between successive arches that rise; stronger: seeds with a later,
#     stronger wave; wall_share: side walls' share of the weight; tc_el: TC-elastic share.
set -euo pipefail
GRANREPRO=${GRANREPRO:-./build/granrepro}
SEEDS=${SEEDS:-32}
REF_SEEDS=${REF_SEEDS:-32}
SCALE=${SCALE:-paper}
OUT=${OUT:-out/studies/pipe-arching-tc}
THREADS=${THREADS:-1}
mkdir -p "$OUT"

# label | seeds | --set assignments (space separated); every row adds g=9.81
rows=(
  "ref:t_c=1e-6,keep|$REF_SEEDS|t_c=1e-6 tc_friction=keep"
  "t_c=3e-5,keep|$SEEDS|t_c=3e-5 tc_friction=keep"
  "t_c=1e-4,keep|$SEEDS|t_c=1e-4 tc_friction=keep"
  "t_c=3e-4,keep|$SEEDS|t_c=3e-4 tc_friction=keep"
  "t_c=3e-5,drop|$SEEDS|t_c=3e-5 tc_friction=drop"
  "t_c=1e-4,drop|$SEEDS|t_c=1e-4 tc_friction=drop"
  "t_c=3e-4,drop|$SEEDS|t_c=3e-4 tc_friction=drop"
  "rough:beta0_w=1,t_c=1e-6|$SEEDS|t_c=1e-6 tc_friction=keep beta0_w=1"
  "rough:beta0_w=1,t_c=1e-4|$SEEDS|t_c=1e-4 tc_friction=keep beta0_w=1"
  "rough:beta0_w=1,mu_w=0.7|$SEEDS|t_c=1e-6 tc_friction=keep beta0_w=1 mu_w=0.7"
)

# get SCALAR SUMMARY, fmt VALUE FORMAT
source "$(dirname "$0")/summary_fields.sh"

cols=(row seeds vbar_t0 gap_all_q25 gap_all_med gap_all_q75 gap_all_max gap_after_q25 gap_after_med gap_after_q75
      gap_after_max crack_frac crack_by_0.060 arch_left_4ms open_below arch_frac t_arch_q25 t_arch_med t_arch_q75
      arch_by_0.056 arch_by_0.05 waves_up wave_steps stronger wall_share tc_el B/A s/seed)
(IFS=$'\t'; echo "${cols[*]}")
for r in "${rows[@]}"; do
  label=${r%%|*}
  rest=${r#*|}
  seeds=${rest%%|*}
  sets=(--set g=9.81)
  for a in ${rest#*|}; do sets+=(--set "$a"); done
  dir="$OUT/$(echo "$label" | tr ',=:' '_-_')"
  s="$dir/pipe-arching/summary.json"
  if [[ ! -f $s ]]; then
    nice -n 10 "$GRANREPRO" pipe-arching --scale "$SCALE" --threads "$THREADS" --quiet --out "$dir" \
      --set n_seeds="$seeds" "${sets[@]}" > "$dir.log" 2>&1 || true
  fi
  if [[ ! -f $s ]]; then echo -e "$label\t(run failed, see $dir.log)"; continue; fi
  line=("$label" "$seeds" "$(fmt "$(get vbar_t0 "$s")" %.4f)")
  for k in opening_max_all_q25 opening_max_all_median opening_max_all_q75 opening_max_all_max \
           opening_max_after_q25 opening_max_after_median opening_max_after_q75 opening_max_after_max; do
    line+=("$(fmt "$(get $k "$s")" %.3f)")
  done
  line+=("$(fmt "$(get crack_fraction "$s")" %.2f)" "$(fmt "$(get crack_time_fraction_by_paper "$s")" %.2f)"
    "$(fmt "$(get arch_left_4ms_median "$s")" %.2f)" "$(fmt "$(get opening_below_median "$s")" %.2f)"
    "$(fmt "$(get arch_fraction "$s")" %.2f)" "$(fmt "$(get t_arch_q25 "$s")" %.3f)"
    "$(fmt "$(get t_arch_median "$s")" %.3f)" "$(fmt "$(get t_arch_q75 "$s")" %.3f)"
    "$(fmt "$(get arch_time_fraction_by_paper "$s")" %.2f)" "$(fmt "$(get arch_by_0.05_fraction "$s")" %.2f)"
    "$(fmt "$(get wave_ascend_share "$s")" %.2f)" "$(fmt "$(get wave_steps_total "$s")" %.0f)"
    "$(fmt "$(get wave_stronger_fraction "$s")" %.2f)" "$(fmt "$(get wall_friction_share "$s")" %.3f)"
    "$(fmt "$(get tc_elastic_share_median "$s")" %.3f)" "$(fmt "$(get B_over_A_median_seeds "$s")" %.2f)"
    "$(fmt "$(get seconds_per_seed_median "$s")" %.1f)")
  (IFS=$'\t'; echo "${line[*]}")
done
