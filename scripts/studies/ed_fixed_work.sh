#!/usr/bin/env bash
# ED speed against an older commit at fixed work: `bench ed` times a CPU-second budget, whose
# wall clock varies +-20 % on a shared VM; this counts the instructions (cachegrind) of the same
# 1e6 collisions from the same start in both builds, minus those of the set-up alone, and checks
# that both end in the same state. Needs valgrind. Usage:
#   scripts/studies/ed_fixed_work.sh OLD_REV [N ...]      (default OLD_REV=2b84036, N = 10000 100000)
# Results of 2026-12-06: scripts/studies/ed_fixed_work.md.
set -euo pipefail
cd "$(dirname "$0")/../.."
old=${1:-2b84036}
[ $# -gt 0 ] && shift
sizes=("$@"); [ $# -gt 0 ] || sizes=(10000 100000)
work=$(mktemp -d); trap 'git worktree remove --force "$work/old" 2>/dev/null || true; rm -rf "$work"' EXIT
git worktree add --detach "$work/old" "$old" > /dev/null
build() { # tree name: its Release library in $work/build-name, then the driver against the tree's
           # headers (the engine, a header template, is compiled into the driver with the same flags)
  cmake -S "$1" -B "$work/build-$2" -DCMAKE_BUILD_TYPE=Release -DGRANREPRO_TESTS=OFF > /dev/null
  cmake --build "$work/build-$2" -j"$(nproc)" --target granrepro_lib > /dev/null
  g++ -O3 -DNDEBUG -std=c++20 -I"$1/src" -I"$1" -isystem /usr/include/eigen3 -isystem /usr/include/hdf5/serial \
    scripts/studies/ed_fixed_work.cpp "$work/build-$2/libgranrepro_lib.a" -lgsl -lgslcblas -lfftw3 -lpthread \
    -o "$work/ed_$2"
}
build "$work/old" old; build "$PWD" new
irefs() { valgrind --tool=cachegrind --cache-sim=no --cachegrind-out-file=/dev/null "$@" 2>&1 |
          sed -n 's/.*I *refs: *//p' | tr -d ,; }
printf '%-8s %-16s %-16s %-8s %s\n' N "Ir $old" "Ir HEAD" change "same final state"
for n in "${sizes[@]}"; do
  o=$(( $(irefs "$work/ed_old" "$n" 1000000) - $(irefs "$work/ed_old" "$n" 0) ))
  h=$(( $(irefs "$work/ed_new" "$n" 1000000) - $(irefs "$work/ed_new" "$n" 0) ))
  same=no; [ "$("$work/ed_old" "$n" 1000000)" = "$("$work/ed_new" "$n" 1000000)" ] && same=yes
  printf '%-8s %-16s %-16s %+.2f %%  %s\n' "$n" "$o" "$h" "$(awk "BEGIN{print 100*($h/$o-1)}")" "$same"
done
