#!/usr/bin/env python3
"""Does ctest in BUILD see every test it should? (scripts/test.sh, after each build)

    python3 scripts/test_counts.py BUILD LABEL...

Nothing here is a hand-kept number. For each LABEL (a ctest label such as unit or repro):
  - ctest has at least one test with it;
  - every test a gtest binary of the label lists (`BINARY --gtest_list_tests`, parameterised
    instances included) is a ctest test: a failed or partial gtest discovery fails;
  - every experiment `BUILD/granrepro list --json` lists has its per-experiment tests (PER_EXPERIMENT
    below: the tests tests/Repro.cmake and the input fuzz test make of each experiment).
A configuration that loses tests (GRANREPRO_TESTS=OFF, a lost label, a failed discovery, an
experiment without its reproduction test) exits 1 with one line naming what is missing; the
per-label counts are printed otherwise. Commands run from an argument vector, never a shell.
"""
import json
import os
import re
import subprocess
import sys

# The tests each experiment gets, per label ({name}: the experiment, {ident}: with '-' as '_', as
# gtest names it). repro: tests/Repro.cmake (run, check, verify, figures; paper_figures.verify for
# the committed results of every experiment); integration: tests/integration/input_fuzz_test.cpp.
PER_EXPERIMENT = {
    "repro": ["repro.{name}.run", "repro.{name}.check", "repro.{name}.verify", "repro.{name}.figures",
              "paper_figures.verify.{name}"],
    "integration": ["Experiments/InputFuzz.EveryProbeIsRefusedInOneNamingLineOrAcceptedQuickly/{ident}",
                    "Experiments/InputFuzzRun.EveryProbeRunsToAResultOrIsRefusedNamingItsParameter/{ident}"],
}


def fail(message):
    print(f"test_counts: {message}", file=sys.stderr)
    sys.exit(1)


def run(argv, cwd=None):
    r = subprocess.run(argv, cwd=cwd, capture_output=True, text=True)
    if r.returncode != 0:
        fail(f"{' '.join(argv)} exited {r.returncode}: {(r.stderr.strip().splitlines() or [''])[-1]}")
    return r.stdout


def gtest_names(binary):
    """The full names `binary --gtest_list_tests` prints (Suite.Test, Prefix/Suite.Test/param)."""
    names, suite = set(), None
    for line in run([binary, "--gtest_list_tests"]).splitlines():
        if not line.strip():
            continue
        if not line.startswith(" "):
            suite = line.split("#")[0].strip()
        else:
            names.add(suite + line.split()[0])
    return names


def main():
    if len(sys.argv) < 3:
        fail("usage: test_counts.py BUILD LABEL...")
    build, labels = sys.argv[1], sys.argv[2:]
    tests = json.loads(run(["ctest", "--show-only=json-v1"], cwd=build))["tests"]
    experiments = [x["name"] for x in json.loads(run([os.path.join(build, "granrepro"), "list", "--json"]))["experiments"]]
    if not experiments:
        fail(f"{build}/granrepro list --json lists no experiment")
    for label in labels:
        mine = [t for t in tests if label in next((p["value"] for p in t.get("properties", [])
                                                   if p["name"] == "LABELS"), [])]
        names = {t["name"] for t in mine}
        if not mine:
            fail(f"{build} has no '{label}' tests")
        # gtest tests as gtest_discover_tests adds them: BINARY --gtest_filter=NAME ...
        by_binary = {}
        for t in mine:
            cmd = t.get("command") or []
            f = next((a for a in cmd[1:] if a.startswith("--gtest_filter=")), None)
            if f:
                by_binary.setdefault(cmd[0], set()).add(f[len("--gtest_filter="):])
        for binary, found in sorted(by_binary.items()):
            lost = sorted(gtest_names(binary) - found)
            if lost:
                fail(f"{build}: {len(lost)} tests of {os.path.basename(binary)} are not '{label}' tests in ctest, "
                     f"e.g. {lost[0]}")
        missing = [p.format(name=n, ident=re.sub("-", "_", n)) for n in experiments for p in PER_EXPERIMENT.get(label, [])]
        missing = [m for m in missing if m not in names]
        if missing:
            fail(f"{build}: {len(missing)} '{label}' tests of the listed experiments are missing, e.g. {missing[0]}")
        per = len(PER_EXPERIMENT.get(label, [])) * len(experiments)
        print(f"test.sh: {build}: {len(mine)} {label} tests"
              + (f" ({sum(map(len, by_binary.values()))} of gtest, every one its binaries list)" if by_binary else "")
              + (f" ({per} for the {len(experiments)} experiments of `granrepro list --json`)" if per else ""))


if __name__ == "__main__":
    main()
