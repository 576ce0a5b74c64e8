#!/usr/bin/env bash
# Issue 26: the wall spacing pinned down by one statement of Schäfer & Wolf (text below Fig. 6: the
# slow branch becomes unstable at e_N ≈ 0.85), at the decisive e_N, k_N = 2000 N/m, slow and fast
# starts, several realizations (seeds). One granrepro run per (spacing, seed); a finished run is
# reused when the script is rerun (delete $OUT to start over).
#
#   scripts/studies/bistable_pipe_spacing.sh [quick|paper]
#
# Environment (defaults in brackets):
#   SPACINGS  wall spacings [m]        [1.0e-3 1.1e-3 1.2e-3 1.3e-3 1.4e-3 1.5e-3]
#   SEEDS     realizations             [1 2 3]
#   EN        e_N grid                 [0.75,0.8,0.825,0.85,0.875,0.9,0.925,0.95]
#   BUDGET    budget_tcol              [1e5: 7.1 s at e_N = 0.7, 9.7 s at 0.9]
#   OUT       results                  [out-studies/bistable-pipe-spacing-<scale>]
#   GRANREPRO binary                   [./build/granrepro]; THREADS [2]; MORE: extra granrepro flags
#   TABLE_ONLY  set: run nothing, tabulate the finished runs only
# Prints, per spacing and e_N, every seed's outcome of each start: the steady speed in m/s
# (below v_crit = 4 m/s: slow branch; above: fast branch), "ff N" free fall (last speed N m/s),
# "un N" unsettled at the end of the budget or stopped at v_abort; a fast start "stays fast" when it
# settles above v_crit or is above it when stopped. Then each spacing's slow-branch edge (the lowest
# grid e_N from which upward a majority of the slow starts settle on the slow branch) and the e_N
# where a majority of both starts keep their branch (bistable).
set -euo pipefail
cd "$(dirname "$0")/../.."
scale=${1:-quick}
bin=${GRANREPRO:-./build/granrepro}
read -r -a spacings <<< "${SPACINGS:-1.0e-3 1.1e-3 1.2e-3 1.3e-3 1.4e-3 1.5e-3}"
read -r -a seeds <<< "${SEEDS:-1 2 3}"
en=${EN:-0.75,0.8,0.825,0.85,0.875,0.9,0.925,0.95}
budget=${BUDGET:-1e5}
out=${OUT:-out-studies/bistable-pipe-spacing-$scale}
read -r -a more <<< "${MORE:-}"

dirs=()
for sp in "${spacings[@]}"; do
  for seed in "${seeds[@]}"; do
    dir="$out/sp$sp-seed$seed"
    if [ -f "$dir/bistable-pipe/tables/steady_k2000.tsv" ]; then dirs+=("$dir"); continue; fi
    [ -n "${TABLE_ONLY:-}" ] && continue
    dirs+=("$dir")
    rc=0
    "$bin" bistable-pipe --scale "$scale" --seed "$seed" --threads "${THREADS:-2}" --quiet \
      --set kN_list=2000 --set eN_list="$en" --set budget_tcol="$budget" --set wall_spacing="$sp" \
      --set length_check=0 "${more[@]}" --out "$dir" > /dev/null || rc=$?
    # exit 1 (a claim of the default grid fails on this grid) is expected; anything else is an error
    if ((rc > 1)); then echo "bistable_pipe_spacing: run $dir failed (exit $rc)" >&2; exit "$rc"; fi
  done
done

python3 - "${dirs[@]}" <<'PY'
import csv, re, sys
from collections import defaultdict
V_CRIT = 4.0  # m/s at k_N = 2000 N/m (experiments/bistable-pipe.toml, v_crit_2000)
cells = defaultdict(lambda: defaultdict(list))  # (spacing, e) -> start -> [(seed, text, branch)]
spacings, ens = [], []
for d in sys.argv[1:]:
    sp, seed = re.search(r"sp([^/]+)-seed(\d+)$", d).groups()
    sp = float(sp)
    if sp not in spacings: spacings.append(sp)
    path = d + "/bistable-pipe/tables/steady_k2000.tsv"
    rows = list(csv.DictReader((l for l in open(path) if not l.startswith("#")), delimiter="\t"))
    for r in rows:
        e = float(r["e_N"])
        if e not in ens: ens.append(e)
        for s in ("slow", "fast"):
            o = int(float(r["outcome_" + s]))
            if o == 0:
                v = float(r["v_" + s])
                cells[(sp, e)][s].append((seed, "%.2f" % v, "slow" if v < V_CRIT else "fast"))
            else:
                cells[(sp, e)][s].append((seed, "%s %.0f" % ("ff" if o == 1 else "un", float(r["v_last_" + s])), o == 1 and "ff" or "un"))
ens.sort(); spacings.sort()
print("| spacing [mm] | e_N | slow starts (per seed) | fast starts (per seed) | slow branch holds | fast start stays fast | bistable |")
print("|---:|---:|---|---|---:|---:|---|")
edges, bistable = {}, {}
for sp in spacings:
    held = []
    for e in ens:
        c = cells[(sp, e)]
        slow_ok = sum(b == "slow" for _, _, b in c["slow"])
        # a fast start stays fast when it settles above v_crit or is still above it when stopped (v_abort)
        fast_ok = sum(b == "fast" or (b != "slow" and float(t.split()[-1]) > V_CRIT) for _, t, b in c["fast"])
        n = len(c["slow"])
        held.append(2 * slow_ok > n)
        bist = 2 * slow_ok > n and 2 * fast_ok > len(c["fast"])
        print("| %.2f | %.3f | %s | %s | %d/%d | %d/%d | %s |" % (sp * 1e3, e, ", ".join(t for _, t, _ in c["slow"]),
              ", ".join(t for _, t, _ in c["fast"]), slow_ok, n, fast_ok, len(c["fast"]), "yes" if bist else ""))
        bistable.setdefault(sp, []).append(e) if bist else None
    edge = None
    for i in range(len(ens) - 1, -1, -1):
        if not held[i]: break
        edge = ens[i]
    edges[sp] = edge
print()
print("| spacing [mm] | slow-branch edge (lowest e_N from which a majority of slow starts stay slow) | bistable e_N (majority of both) |")
print("|---:|---|---|")
for sp in spacings:
    print("| %.2f | %s | %s |" % (sp * 1e3, "none on the grid" if edges[sp] is None else "%.3f" % edges[sp],
          ", ".join("%.3f" % e for e in bistable.get(sp, [])) or "none"))
PY
