#!/usr/bin/env bash
# The test job: install dependencies, build (Release) into build-test/ with the tests, check that
# ctest sees every kind of test, run every ctest label (unit, integration, validation, repro, sweep,
# report, hostile_results; repro includes the re-check of the committed paper-scale results and the
# gnuplot-warning check of every figure, report loads the HTML report in headless Chromium,
# hostile_results runs every reader on crafted results folders), then rebuild into build-asan/ with
# AddressSanitizer + UBSan and run the unit, integration and hostile_results tests again (the
# integration and hostile tests spawn the sanitized binary). One line per phase, naming its log;
# the counts printed are ctest's own (`ctest -N` with the same selection as the run).
set -euo pipefail
cd "$(dirname "$0")/.."
echo "test.sh: [1/5] install what is missing (apt log: ${SETUP_LOG:-/tmp/granrepro-setup.log})"
bash scripts/setup.sh
jobs=$(nproc)

# Every kind of test is there: scripts/test_counts.py checks, per label, that ctest has tests with
# it, that every test its gtest binaries list is a ctest test, and that every experiment
# `granrepro list --json` lists has its repro and fuzz tests. No count is kept by hand: a
# configuration that loses tests (e.g. GRANREPRO_TESTS=OFF, a failed gtest discovery, an
# experiment without its tests) fails here instead of passing with "No tests were found".
require_tests() { local dir=$1; shift; python3 scripts/test_counts.py "$dir" "$@" || exit 1; }

build() { # folder, build type, targets ("" = all; space-separated), more cmake options...
  local dir=$1 type=$2 targets=$3
  shift 3
  cmake -S . -B "$dir" -DCMAKE_BUILD_TYPE="$type" -DGRANREPRO_TESTS=ON "$@" > /dev/null
  # shellcheck disable=SC2086 # targets split on purpose
  bash scripts/build_progress.sh "$dir" "$jobs" ${targets:+--target $targets} || exit 1
}
# How many tests ctest would run with these selection options (-L, -E), as ctest counts them.
selected() { local dir=$1; shift; (cd "$dir" && ctest -N "$@" | sed -n 's/^Total Tests: //p'); }

echo "test.sh: [2/5] build (Release, with the tests) into build-test/"
build build-test Release ""
require_tests build-test unit integration validation repro sweep report hostile_results
echo "test.sh: [3/5] ctest in build-test/: $(selected build-test) tests (each test's output: build-test/Testing/Temporary/LastTest.log)"
(cd build-test && ctest -j"$jobs" --no-tests=error --output-on-failure)

echo "test.sh: [4/5] build (Debug, ASan + UBSan) into build-asan/"
build build-asan Debug "unit_tests integration_tests hostile_results_tests" -DGRANREPRO_SANITIZE=ON
require_tests build-asan unit integration hostile_results
# The input fuzz tests (about 2,500 refused inputs, and InputFuzzRun: ~250 short runs of the engines at
# extreme accepted inputs; both in the Release pass above) took 12 min and more under
# the sanitizers on 2 cores (at -O0); the sanitizer pass runs every other unit and integration test.
asan_selection=(-L '^(unit|integration|hostile_results)$' -E '^Experiments/InputFuzz')
echo "test.sh: [5/5] ctest in build-asan/: $(selected build-asan "${asan_selection[@]}") tests under ASan/UBSan (the input fuzz tests excluded; log: build-asan/Testing/Temporary/LastTest.log)"
(cd build-asan && ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 \
   ctest -j"$jobs" "${asan_selection[@]}" --no-tests=error --output-on-failure)
echo "test.sh: done: $(selected build-test) tests in build-test/ and $(selected build-asan "${asan_selection[@]}") in build-asan/ passed"
