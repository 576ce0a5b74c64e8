#!/bin/bash
# Fig. 6 at paper scale as a Slurm job array without MPI: 8 tasks each compute every 8th sweep
# point into out/.bistable-pipe.checkpoint/ (shared file system); then one job writes the results.
#SBATCH --job-name=granrepro-fig6 --array=1-8 --cpus-per-task=2 --time=04:00:00
set -euo pipefail
flags=(--scale paper --out out --threads "${SLURM_CPUS_PER_TASK:-1}" --quiet)
./build/granrepro bistable-pipe "${flags[@]}"   # shard $SLURM_ARRAY_TASK_ID of $SLURM_ARRAY_TASK_COUNT
# After every task: sbatch --dependency=afterok:<array job id> --wrap \
#   './build/granrepro gather bistable-pipe --scale paper --out out'   (exit 2 names missing points)
