#!/usr/bin/env bash
# Builds one CMake folder with its whole output in <dir>/build.log and one progress line per
# tenth on stdout, so a newcomer sees the 5 to 15 minutes of a first build move.
# Usage: build_progress.sh DIR JOBS [cmake --build options...]; exit status of the build.
set -uo pipefail
dir=$1 jobs=$2
shift 2
echo "  build $dir (log: $dir/build.log)"
cmake --build "$dir" -j"$jobs" "$@" 2>&1 | tee "$dir/build.log" |
  awk '/^\[ *[0-9]+%\]/ { p = substr($0, 2, 3) + 0; if (p >= next_p) { printf "  build %s: %d%%\n", dir, p; fflush(); next_p = p - p % 10 + 10 } }' dir="$dir" next_p=10
status=${PIPESTATUS[0]}
((status == 0)) || tail -n 40 "$dir/build.log" >&2
exit "$status"
