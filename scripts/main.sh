#!/usr/bin/env bash
# The main job: install dependencies, build (Release) into build/, reproduce every figure at the
# given scale (default quick), print the check table (one per experiment) and the totals line.
# Results in out/, figures in out/<experiment>/. Exit code 1 if a claim fails.
# The build log is build/build.log; progress appears only on a terminal.
set -euo pipefail
cd "$(dirname "$0")/.."
scale=${1:-quick}
bash scripts/setup.sh
# build/ is the program's folder (the README's ./build/granrepro); scripts/test.sh builds the
# tests in build-test/, so neither reconfigures the other's folder.
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DGRANREPRO_TESTS=OFF > /dev/null
if ! cmake --build build -j"$(nproc)" --target granrepro > build/build.log; then
  tail -n 40 build/build.log >&2
  exit 1
fi
./build/granrepro all --scale "$scale" --threads "$(nproc)" --out out
