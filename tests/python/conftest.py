# Shared by the Python tests: the granrepro binary (GRANREPRO_BINARY, set by ctest) and one
# quick-scale run of brake-failure and emergency-brake (a few seconds) in a temporary --out.
import os
import subprocess
import sys

import pytest

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "..", "python"))


@pytest.fixture(scope="session")
def binary():
    b = os.environ.get("GRANREPRO_BINARY")
    if not b:
        pytest.fail("GRANREPRO_BINARY is not set (ctest sets it)")
    return b


@pytest.fixture(scope="session")
def quick_out(binary, tmp_path_factory):
    out = tmp_path_factory.mktemp("quick")
    for exp in ("brake-failure", "emergency-brake"):
        sets = ["--set", "n_positions=3", "--seed", "7"] if exp == "emergency-brake" else []
        rc = subprocess.run([binary, exp, "--scale", "quick", "--quiet", "--threads", "2", *sets, "--out", str(out)],
                            stdout=subprocess.DEVNULL).returncode
        assert rc in (0, 1), f"{exp} exited {rc}"
    return out
