#!/usr/bin/env bash
# A new experiment end to end (issue 44): the toy of tests/toy/ is added to a copy of granrepro's
# data files as ARCHITECTURE.md's worked example adds one, and run through the harness by
# granrepro_toy (granrepro with tests/toy/registry.cpp's list: granrepro's and one line). It fails
# if the toy needs more than six files by hand, or if the run, the check, the figure or the
# listing does not take it.
#   toy_test.sh GRANREPRO_TOY SOURCE_DIR
set -euo pipefail
bin=${1:?usage: toy_test.sh GRANREPRO_TOY SOURCE_DIR}
src=${2:?usage: toy_test.sh GRANREPRO_TOY SOURCE_DIR}
toy=$src/tests/toy
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# The files a new experiment touches by hand: its parameters, its C++, its registry line, its
# claims, its plot script and its caption. This script is the test, not one of them.
mapfile -t files < <(cd "$toy" && find . -type f ! -name toy_test.sh | sort)
printf 'toy_test: the toy touches %d files by hand:' "${#files[@]}"; printf ' %s' "${files[@]}"; echo
if ((${#files[@]} > 6)); then echo "toy_test: more than 6 files" >&2; exit 1; fi

# granrepro's data files with the toy's added (GRANREPRO_HOME: the data root of granrepro_toy).
home=$work/home
mkdir -p "$home/experiments" "$home/expected" "$home/plots" "$home/python/granrepro/report"
cp "$src"/experiments/*.toml "$toy/experiments/toy.toml" "$home/experiments/"
cp "$src"/expected/*.toml "$toy/expected/toy.toml" "$home/expected/"
cp "$src"/plots/*.gp "$toy/plots/toy26-fig1.gp" "$home/plots/"
cat "$src/python/granrepro/report/figures.toml" "$toy/figures.toml" > "$home/python/granrepro/report/figures.toml"
export GRANREPRO_HOME=$home

"$bin" list --json > "$work/list.json"
python3 - "$work/list.json" <<'PY'
import json, sys
names = [e["name"] for e in json.load(open(sys.argv[1]))["experiments"]]
assert names[-1] == "toy", f"toy_test: list --json does not end with the toy: {names}"
PY
"$bin" toy --quiet --out "$work/out"            # runs, checks its claims (exit 1 on a FAIL) and draws
test -s "$work/out/toy/toy26-fig1.png" || { echo "toy_test: no figure toy26-fig1.png" >&2; exit 1; }
"$bin" check toy --out "$work/out" > "$work/check.txt"
grep -q 'e_N_eq4 .*PASS' "$work/check.txt" || { cat "$work/check.txt"; echo "toy_test: claim e_N_eq4 did not pass" >&2; exit 1; }
"$bin" verify toy --out "$work/out" > /dev/null
echo "toy_test: the toy runs, passes its claim, draws its figure, verifies and is listed"
