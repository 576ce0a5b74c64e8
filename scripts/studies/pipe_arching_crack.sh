#!/usr/bin/env bash
# Issue 43 §1 (Luding 1998 Sec. 5, Fig. 13: the crack), the runs that need no change to the program:
# item 1 (a local opening at the initiating disk, re-scored on stored frames) and item 5 (interparticle
# ε = 0.8 / 0.95 and β0 = 0.0 / 0.6, 16 seeds each), with the arch's lifetime judged in the same runs.
# Items 2-4 (wall-surface jitter, lattice registration, relaxation from v0) need new program code
# and are not made here.
#
#   scripts/studies/pipe_arching_crack.sh        (from the source tree, after building build/granrepro)
#
# Environment: GRANREPRO (default ./build/granrepro), SEEDS (default 16), OUT (default
# out-studies/pipe-arching-crack), COMMITTED (default paper_figures/pipe-arching/data.h5), PY
# (default /usr/bin/python3, with h5py and numpy), NICE (default 15), DEPTH (how far below the initiating
# disk's centre the local opening is searched, default 10 d; the .md reports 3 and 20 d too).
#
# Per config (default; epsilon=0.8; epsilon=0.95; beta0=0.0; beta0=0.6; every other parameter at its
# paper-scale value) two kinds of run, both paper scale, --threads 1, kept in $OUT/<config>/ and
# reused when finished:
#   1. `granrepro pipe-arching --scale paper --set n_seeds=16 --set <config>`: the experiment's own
#      per-seed outcomes (wall-to-wall detector, opening_below, arch_left_4ms). For the default the
#      committed paper-scale run ($COMMITTED, 32 seeds) stands in for it.
#   2. the frame runs: the stored results hold the disks' positions only for run 0 (seed index 0) and
#      only at snapshot_times, so the local opening of every seed needs its frames. Run 0 of a run is
#      RngStream(seed, 0), so each seed S = 1..SEEDS is one run `--seed S --set n_seeds=1 --set
#      snapshot_times=0.010,0.011,...,0.100` (every frame of the fall a snapshot, run 0's marks give
#      the initiating disk in each). --seed 1 is run 0 of run 1 bit for bit; seeds 2..16 are new draws
#      of the same ensemble (not seeds 1..15 of run 1, which draw RngStream(1, k)).
# Then pipe_arching_crack.py (beside this script) computes the local openings and prints the tables
# (pipe_arching_crack.md holds them with what they decide).
set -euo pipefail
GRANREPRO=${GRANREPRO:-./build/granrepro}
SEEDS=${SEEDS:-16}
OUT=${OUT:-out-studies/pipe-arching-crack}
COMMITTED=${COMMITTED:-paper_figures/pipe-arching/data.h5}
PY=${PY:-/usr/bin/python3}
NICE=${NICE:-15}
mkdir -p "$OUT"
# The frame runs draw no figures: their Fig. 13 would have 91 panels (82 MB of PDF, a minute per run
# against 4 s for the seed itself). A `gnuplot` that fails at once, first on PATH for those runs
# only, makes the program skip the figures ("not drawn", exit 4) after writing data.h5.
nognuplot="$(realpath "$OUT")/.no-gnuplot"
mkdir -p "$nognuplot"
printf '#!/bin/sh\nexit 1\n' > "$nognuplot/gnuplot"
chmod +x "$nognuplot/gnuplot"

# name | --set assignments (space separated)
configs=(
  "default|"
  "epsilon-0.8|epsilon=0.8"
  "epsilon-0.95|epsilon=0.95"
  "beta0-0.0|beta0=0.0"
  "beta0-0.6|beta0=0.6"
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
  name=${c%%|*}
  sets=()
  for a in ${c#*|}; do sets+=(--set "$a"); done
  names+=("$name")
  if [[ $name != default ]]; then run "$PATH" "$OUT/$name" --set n_seeds="$SEEDS" "${sets[@]}"; fi
  for s in $(seq 1 "$SEEDS"); do
    run "$nognuplot:$PATH" "$OUT/$name/frames/seed$s" --seed "$s" --set n_seeds=1 --set snapshot_times="$frames" "${sets[@]}"
  done
done

"$PY" "$(dirname "$0")/pipe_arching_crack.py" "$OUT" "$COMMITTED" "${names[@]}"
