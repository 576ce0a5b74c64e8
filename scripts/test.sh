#!/usr/bin/env bash
# The test job: install dependencies, build (Release) into build-test/ with the tests, check that
# ctest sees every kind of test, run every ctest label (unit, integration, validation, repro, sweep,
# report; repro includes the re-check of the committed paper-scale results and the gnuplot-warning
# check of every figure, report loads the HTML report in headless Chromium), then rebuild into
# build-asan/ with AddressSanitizer + UBSan and run the unit and integration tests again (the
# integration tests spawn the sanitized binary).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
jobs=$(nproc)

# At least this many tests per label (the counts when this was written; they only grow). A
# configuration that loses tests (e.g. GRANREPRO_TESTS=OFF, a failed gtest discovery) fails here
# instead of passing with "No tests were found".
min_unit=214
min_integration=105
min_validation=25
min_repro=46
min_sweep=13
min_report=11

count() { (cd "$1" && ctest -N -L "^$2\$" | sed -n 's/^Total Tests: //p'); }
require_tests() {
  local dir=$1 label=$2 min=$3 n
  n=$(count "$dir" "$label")
  if ((${n:-0} < min)); then
    echo "test.sh: $dir has ${n:-0} '$label' tests, expected at least $min" >&2
    exit 1
  fi
  echo "test.sh: $dir: $n $label tests"
}

build() { # folder, build type, target ("" = all), more cmake options...
  local dir=$1 type=$2 target=$3
  shift 3
  cmake -S . -B "$dir" -DCMAKE_BUILD_TYPE="$type" -DGRANREPRO_TESTS=ON "$@" > /dev/null
  if ! cmake --build "$dir" -j"$jobs" ${target:+--target "$target"} > "$dir/build.log"; then
    tail -n 40 "$dir/build.log" >&2
    exit 1
  fi
}

build build-test Release ""
require_tests build-test unit "$min_unit"
require_tests build-test integration "$min_integration"
require_tests build-test validation "$min_validation"
require_tests build-test repro "$min_repro"
require_tests build-test sweep "$min_sweep"
require_tests build-test report "$min_report"
(cd build-test && ctest -j"$jobs" --no-tests=error --output-on-failure)

build build-asan Debug unit_tests -DGRANREPRO_SANITIZE=ON
build build-asan Debug integration_tests -DGRANREPRO_SANITIZE=ON
require_tests build-asan unit "$min_unit"
require_tests build-asan integration "$min_integration"
# The input fuzz tests (about 2,500 refused inputs, and InputFuzzRun: ~250 short runs of the engines at
# extreme accepted inputs; both in the Release pass above) take 12 min and more under
# the sanitizers on 2 cores; the sanitizer pass runs every other unit and integration test.
(cd build-asan && ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 \
   ctest -j"$jobs" -L '^(unit|integration)$' -E '^Experiments/InputFuzz' --no-tests=error --output-on-failure)
