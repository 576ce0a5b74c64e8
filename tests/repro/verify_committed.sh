#!/usr/bin/env bash
# CI (ctest label repro): `granrepro verify EXPERIMENT --point-only --out DIR` on committed
# results. Passes when the cheapest stored point reproduces; any mismatch (exit 1) or refusal
# fails.
#   verify_committed.sh GRANREPRO DIR EXPERIMENT
set -uo pipefail
bin=$1 dir=$2 exp=$3
err=$(mktemp)
trap 'rm -f "$err"' EXIT
"$bin" verify "$exp" --point-only --out "$dir" 2> "$err"
rc=$?
cat "$err" >&2
if ((rc == 0)); then
  exit 0
fi
echo "verify_committed: $dir/$exp: verify exited $rc" >&2
exit 1
