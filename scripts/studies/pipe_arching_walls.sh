#!/usr/bin/env bash
# Issue 43 §1 (Luding 1998 Sec. 5, Fig. 13: the crack and the arch's life), the runs that need the
# options added for them: item 2 (side-wall jitter, parameter wall_jitter), item 3 (lattice
# registration, parameter registration) and item 4 (the relaxation from v0 without gravity,
# parameter relax_gravity), each scored by both crack detectors (the wall-to-wall detector of the
# experiment and the local opening at the initiating disk of pipe_arching_crack.py), with the
# arch's lifetime (arch_left_4ms) from the same runs, the interparticle rows of pipe_arching_crack.sh
# (epsilon 0.8, 0.95; beta0 0.0, 0.6) rerun as frame runs for one table; and the default at 64 seeds (claims
# waves_ascend, B_rate on the arch-relative B_rel).
#
#   scripts/studies/pipe_arching_walls.sh        (from the source tree, after building build/granrepro)
#
# Environment: GRANREPRO (default ./build/granrepro), OUT (default out-studies/pipe-arching-walls),
# PY (default /usr/bin/python3, with h5py and numpy), NICE (default 10), ONLY (a config name: run
# only that one; empty: all, then the tables).
#
# Every config is a set of frame runs, paper scale, --threads 1: seed S = 1..n is run 0 of its own
# run, `granrepro pipe-arching --scale paper --seed S --set n_seeds=1 --set
# snapshot_times=0.010,0.011,...,0.100 --set <config>` (every frame a snapshot, so the local opening
# can be measured at the initiating disk; run 0's outcome holds the wall-to-wall detector, the arch
# and its lifetime). --seed 1 is run 0 of the committed run bit for bit (defaults unchanged); the
# jitter and the random registration are drawn from the run's own RngStream after the velocities.
# And the multi-seed runs (seeds 0 in the list) `granrepro pipe-arching --scale paper --set n_seeds=64` (also 100,
# and 32 with --set t_arch_paper=0.054). The tables go to $OUT/tables.md, one line per config to pipe_arching_walls.tsv (TSV).
set -euo pipefail
GRANREPRO=${GRANREPRO:-./build/granrepro}
OUT=${OUT:-out-studies/pipe-arching-walls}
PY=${PY:-/usr/bin/python3}
NICE=${NICE:-10}
ONLY=${ONLY:-}
mkdir -p "$OUT"
# The frame runs draw no figures (91 panels each): a failing `gnuplot` first on their PATH makes
# the program skip them ("not drawn") after writing data.h5 (as pipe_arching_crack.sh).
nognuplot="$(realpath "$OUT")/.no-gnuplot"
mkdir -p "$nognuplot"
printf '#!/bin/sh\nexit 1\n' > "$nognuplot/gnuplot"
chmod +x "$nognuplot/gnuplot"

# name | seeds | --set assignments (space separated)
configs=(
  "default|16|"
  "jitter-0.05|32|wall_jitter=0.05"
  "registration-random|16|registration=random"
  "registration-centred|16|registration=centred"
  "jitter-0.01|32|wall_jitter=0.01"
  "jitter-0.03|32|wall_jitter=0.03"
  "seeds64|0|n_seeds=64"
  "seeds100|0|n_seeds=100"
  "tarch-0.054|0|n_seeds=32 t_arch_paper=0.054"
  "relax-nog|16|relax_gravity=off v0=0.0612 g=9.81"
  "epsilon-0.8|16|epsilon=0.8"
  "epsilon-0.95|16|epsilon=0.95"
  "beta0-0.0|16|beta0=0.0"
  "beta0-0.6|16|beta0=0.6"
)
frames=$(seq -f %.3f 0.010 0.001 0.1004 | paste -sd, -)

run() { # PATH DIR ARGS...: one run unless its summary.json exists; user, system, wall s to DIR.time
  local path=$1 dir=$2; shift 2
  [[ -f $dir/pipe-arching/summary.json ]] && return 0
  mkdir -p "$dir"
  PATH=$path /usr/bin/time -f "%U %S %e" -o "$dir.time" nice -n "$NICE" "$GRANREPRO" pipe-arching --scale paper --threads 1 \
    --quiet --out "$dir" "$@" > "$dir.log" 2>&1 || true
  [[ -f $dir/pipe-arching/summary.json ]] || { echo "run failed: $dir (see $dir.log)" >&2; return 1; }
}

names=()
for c in "${configs[@]}"; do
  IFS='|' read -r name seeds assigns <<< "$c"
  sets=()
  for a in $assigns; do sets+=(--set "$a"); done
  if [[ $seeds == 0 ]]; then # one multi-seed run, no frames: its summary.json (claims waves_ascend, B_rate,
    # plug_separates at 64 seeds; 100 seeds: the rule 'single run' decides a fraction near 0.1 on >= 100; B_rel with
    # the Fig. 14(b) times 1..31 ms after each seed's arch instead of -1..29 ms)
    if [[ -z $ONLY || $ONLY == "$name" ]]; then run "$nognuplot:$PATH" "$OUT/$name" "${sets[@]}"; fi
    continue
  fi
  names+=("$name")
  [[ -n $ONLY && $ONLY != "$name" ]] && continue
  for s in $(seq 1 "$seeds"); do
    run "$nognuplot:$PATH" "$OUT/$name/frames/seed$s" --seed "$s" --set n_seeds=1 --set snapshot_times="$frames" ${sets[@]+"${sets[@]}"}
  done
done
[[ -n $ONLY ]] && exit 0
TSV=${TSV:-$(dirname "$0")/pipe_arching_walls.tsv} "$PY" "$(dirname "$0")/pipe_arching_crack.py" "$OUT" none "${names[@]}" > "$OUT/tables.md"
cat "$OUT/tables.md"
