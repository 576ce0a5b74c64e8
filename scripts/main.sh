#!/usr/bin/env bash
# The main job: install dependencies, build (Release), reproduce every figure at the given scale
# (default quick), print the check table. Results in out/, figures in out/<experiment>/.
set -euo pipefail
cd "$(dirname "$0")/.."
scale=${1:-quick}
bash scripts/setup.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DGRANREPRO_TESTS=OFF > /dev/null
cmake --build build -j"$(nproc)" --target granrepro
./build/granrepro all --scale "$scale" --threads "$(nproc)" --out out
