#!/usr/bin/env bash
# The main job: install dependencies, build (Release) into build/, reproduce every figure at the
# given scale (default quick), print the check table (one per experiment) and the totals line.
# Results in out/, figures in out/<experiment>/. Exit code 1 if a claim fails.
# One line per phase, naming its log; the build prints its progress every tenth (build/build.log
# holds the compiler's output).
set -euo pipefail
cd "$(dirname "$0")/.."
scale=${1:-quick}
echo "main.sh: [1/3] install what is missing (apt log: ${SETUP_LOG:-/tmp/granrepro-setup.log})"
bash scripts/setup.sh
# build/ is the program's folder (the README's ./build/granrepro); scripts/test.sh builds the
# tests in build-test/, so neither reconfigures the other's folder.
echo "main.sh: [2/3] build (Release) into build/"
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DGRANREPRO_TESTS=OFF > /dev/null
bash scripts/build_progress.sh build "$(nproc)" --target granrepro || exit 1
echo "main.sh: [3/3] every experiment at --scale $scale into out/ (each run's log: out/<experiment>/run.log)"
./build/granrepro all --scale "$scale" --threads "$(nproc)" --out out
