#!/usr/bin/env bash
# Regenerates paper_figures/ from paper-scale runs of every experiment at one clean commit.
#   scripts/paper_figures.sh            run (or resume) every experiment, then collect
#   scripts/paper_figures.sh --collect  run nothing, only collect the finished runs of this commit
#   scripts/paper_figures.sh --recheck  run nothing, rewrite paper_figures/CHECK.md and report/ from the
#                                       committed numbers with this binary's claims (after a change to
#                                       expected/ only: claims change verdicts, not data)
# Refuses a dirty tree (tracked files modified) and a binary not built from HEAD: paper_figures/
# must come from one commit (CI: tests/repro/physics_hashes.sh). Runs go to a staging folder,
# $OUT (default out-paper-<commit>/); the same command resumes: finished experiments of this
# commit are kept, an interrupted one resumes from its checkpoint (sweep points, long runs).
# Once all are finished, paper_figures/ is rebuilt in paper_figures.new/ and swapped in:
#   <figure>.png                   every figure
#   <experiment>/summary.json      as the run wrote it
#   <experiment>/data.h5           the compact copy (`granrepro export`: tables, parameters,
#                                  scalars, every sweep point; snapshots left out)
#   RUN.json                       the commit, code version, physics hash, start and end of the
#                                  whole regeneration, and per experiment and in all the wall
#                                  and CPU time including resumed points (total_wall_time_s,
#                                  total_cpu_time_s of each summary.json)
#   CHECK.md                       `granrepro check` of the committed numbers, as CI runs it
set -euo pipefail
cd "$(dirname "$0")/.."
bin=./build/granrepro
max_mb=20
scale=${SCALE:-paper} # SCALE=quick: a trial of this script (minutes); never commit its paper_figures/
collect_only=0
recheck=0
case "${1:-}" in
  --collect) collect_only=1 ;;
  --recheck) recheck=1 ;;
  "") ;;
  *) echo "paper_figures.sh: unknown argument '$1'; allowed: --collect, --recheck" >&2; exit 2 ;;
esac

if [ -n "$(git status --porcelain --untracked-files=no)" ]; then
  echo "paper_figures.sh: the working tree has uncommitted changes; commit or stash them (paper_figures/ comes from one clean commit)" >&2
  git status --short --untracked-files=no >&2
  exit 2
fi
commit=$(git rev-parse --short=7 HEAD)
version=$("$bin" --version | sed -n '1s/^granrepro //p') # sed reads it all: no SIGPIPE under pipefail
case "$version" in
  *dirty*|*unknown*) echo "paper_figures.sh: $bin reports '$version': rebuild from the clean tree (cmake --build build)" >&2; exit 2 ;;
esac
if [[ "$version" != *"$commit"* ]]; then
  echo "paper_figures.sh: $bin is '$version', not built from HEAD $commit: rebuild (cmake --build build)" >&2
  exit 2
fi
# The registered experiments, in registry order (`granrepro list --json`, docs/schema.md).
experiments=$("$bin" list --json | python3 -c 'import json, sys; print(" ".join(x["name"] for x in json.load(sys.stdin)["experiments"]))')
# CHECK.md of the results in $1 (made at code version $2): every experiment's check table with its
# known deviations explained, and the totals, as CI runs it.
write_check() {
  local dir=$1 made_at=$2
  {
    echo "# Check table of the paper-scale runs that made these figures"
    echo
    echo "Made by scripts/paper_figures.sh from the runs at $made_at (paper_figures/RUN.json: the whole"
    echo "run's wall and CPU time, resumed points included; each data.h5 holds every sweep point,"
    echo "\`granrepro verify <experiment> --list\`), judged with the claims of expected/ at $(git rev-parse --short=7 HEAD)."
    echo "Re-check with \`./build/granrepro check --all --out paper_figures\` (\`--explain\` prints the known deviations)."
    echo "The headline counts the reproductions only (role = reproduction, expected/README.md \"Roles and statuses\"); identity,"
    echo "calibration and validation claims are counted apart and still fail the check when they fail."
    echo
    echo '```'
    "$bin" check --all --missing-ok --out "$dir" 2>&1 | grep -E ' statements — |, not in the headline: |^totals:' || true
    echo '```'
    echo
    echo '```'
    for e in $experiments; do
      line=$(python3 -c 'import json, sys; d = json.load(open(sys.argv[1])); print(d["code_version"], "seed", d["seed"], "%.0f s wall, %.0f s CPU" % (d.get("total_wall_time_s") or d["wall_time_s"], d.get("total_cpu_time_s") or 0))' \
               "$dir/$e/summary.json")
      echo "# $e: $line"
      "$bin" check "$e" --out "$dir" --explain || true
      echo
    done
    "$bin" check --all --missing-ok --out "$dir" 2>&1 | grep -E ' statements — |, not in the headline: |^totals:|no results' || true
    echo '```'
  } > "$dir/CHECK.md"
  # The reviewer's report of these results (granrepro report), linked from the README.
  "$bin" report --out "$dir" > /dev/null
}
if ((recheck)); then
  write_check paper_figures "$(python3 -c 'import json; print(json.load(open("paper_figures/RUN.json"))["code_version"])')"
  echo "paper_figures/CHECK.md and paper_figures/report/ rewritten with the claims of $commit; git add paper_figures && git commit"
  exit 0
fi
out=${OUT:-out-$scale-$commit}
mkdir -p "$out"
# The start of the whole regeneration, kept across resumes.
[ -f "$out/.started" ] || date -u +%Y-%m-%dT%H:%M:%SZ > "$out/.started"
threads=$(nproc)

# A finished run of this code version at paper scale (the argument goes in as argv, not as code).
finished() {
  [ -f "$out/$1/summary.json" ] && python3 - "$out/$1/summary.json" "$version" "$scale" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
sys.exit(0 if s.get("scale") == sys.argv[3] and s.get("code_version") == sys.argv[2] else 1)
PY
}

if ((!collect_only)); then
  for e in $experiments; do
    if finished "$e"; then
      echo "paper_figures.sh: $e: finished at $version, kept"
      continue
    fi
    echo "paper_figures.sh: $e: running at $scale scale (--threads $threads) into $out"
    rc=0
    "$bin" "$e" --scale "$scale" --threads "$threads" --out "$out" --quiet > "$out/.$e.check.txt" || rc=$?
    if ((rc != 0 && rc != 1)); then
      echo "paper_figures.sh: $e exited $rc; rerun this command to resume" >&2
      exit "$rc"
    fi
  done
fi
missing=""
for e in $experiments; do finished "$e" || missing="$missing $e"; done
if [ -n "$missing" ]; then
  echo "paper_figures.sh: not finished at $version:$missing; run scripts/paper_figures.sh (it resumes)" >&2
  exit 1
fi

new=paper_figures.new
rm -rf "$new"
mkdir -p "$new"
for e in $experiments; do
  cp "$out/$e"/*.png "$new"/ 2>/dev/null || true
  "$bin" export "$e" --out "$out" --to "$new" > /dev/null
done
python3 - "$new" "$out" "$commit" "$version" "$(cat "$out/.started")" "$(date -u +%Y-%m-%dT%H:%M:%SZ)" $experiments <<'PY'
import json, os, sys
new, out, commit, version, started, ended, *names = sys.argv[1:]
runs, wall, cpu, physics = {}, 0.0, 0.0, set()
for n in names:
    s = json.load(open(os.path.join(out, n, "summary.json")))
    physics.add(s.get("physics_hash"))
    runs[n] = {k: s.get(k) for k in ("total_wall_time_s", "total_cpu_time_s", "wall_time_s", "cpu_time_s",
                                     "resumed_points", "points_without_cost", "stored_points", "seed", "command_line")}
    wall += s.get("total_wall_time_s") or 0.0
    cpu += s.get("total_cpu_time_s") or 0.0
if len(physics) != 1:
    sys.exit(f"paper_figures.sh: the runs record {len(physics)} physics hashes: {sorted(map(str, physics))}")
run = {"schema": "granrepro-paper-figures-run", "schema_version": 1, "commit": commit, "code_version": version,
       "physics_hash": physics.pop(), "started_utc": started, "ended_utc": ended,
       "total_wall_time_s": wall, "total_cpu_time_s": cpu,
       "note": "total_*: the sum over experiments of each run's whole time, resumed points included; "
               "started/ended: the regeneration's first start and its collection, pauses between resumes included",
       "experiments": runs}
json.dump(run, open(os.path.join(new, "RUN.json"), "w"), indent=2)
open(os.path.join(new, "RUN.json"), "a").write("\n")
PY
write_check "$new" "$version"
size_kb=$(du -sk "$new" | cut -f1)
if ((size_kb > max_mb * 1024)); then
  echo "paper_figures.sh: $new/ is $((size_kb / 1024)) MB, above the ${max_mb} MB limit: lower --max-table-values of the export; paper_figures/ left as it was" >&2
  exit 1
fi
rm -rf paper_figures.old
[ -d paper_figures ] && mv paper_figures paper_figures.old
mv "$new" paper_figures
rm -rf paper_figures.old
# The report names the folder it reads (issue 40 §6), so it is written again from its final place,
# as `--recheck` and test_report.py write it.
"$bin" report --out paper_figures > /dev/null
echo "paper_figures/ regenerated at $commit from $out ($((size_kb / 1024)) MB); git add paper_figures && git commit"
