#!/usr/bin/env bash
# CI (ctest label repro): paper_figures/ must not mix code versions whose physics differ. Every
# committed summary.json records physics_hash (schema 3; cmake/WriteVersion.cmake says what it
# covers). Fails when two experiments' hashes differ, or when some record one and others do not
# (a partial regeneration). Results that all predate physics hashes pass only when they come from one
# clean code version.
#   physics_hashes.sh DIR
set -euo pipefail
dir=${1:?usage: physics_hashes.sh DIR}
python3 - "$dir" <<'PY'
import glob, json, os, sys
d = sys.argv[1]
found = {}
for f in sorted(glob.glob(os.path.join(d, "*", "summary.json"))):
    s = json.load(open(f))
    found[os.path.basename(os.path.dirname(f))] = (s.get("physics_hash"), s.get("code_version", "?"))
if not found:
    print(f"physics_hashes: no results in {d}")
    sys.exit(0)
for name, (h, v) in found.items():
    print(f"  {name:18s} {h or '(no physics_hash: written before them)':45s} {v}")
hashes = {h for h, _ in found.values()}
if hashes == {None}:
    # Without hashes, one clean code version is the proof of one physics (stricter than a hash).
    versions = {v for _, v in found.values()}
    if len(versions) == 1 and not next(iter(versions)).endswith("-dirty"):
        print(f"physics_hashes: {d}: every result predates physics hashes; one clean code version, {versions.pop()}")
        sys.exit(0)
    print(f"physics_hashes: {d}: results written before physics hashes come from " + ", ".join(sorted(versions)) +
          ": their physics cannot be shown to be one (regenerate with scripts/paper_figures.sh)", file=sys.stderr)
    sys.exit(1)
if len(hashes) > 1:
    print(f"physics_hashes: {d} mixes {len(hashes)} physics: " +
          "; ".join(f"{h or 'none'}: " + ", ".join(n for n, (x, _) in found.items() if x == h) for h in sorted(hashes, key=str)) +
          " (regenerate with scripts/paper_figures.sh)", file=sys.stderr)
    sys.exit(1)
print(f"physics_hashes: {d}: one physics, {hashes.pop()}")
PY
