# A results folder is untrusted input (issue 40): the Python side. Each test crafts a copy of a
# quick brake-failure result (conftest's quick_out) beside a hashed sentinel tree, then requires
# `python3 -m granrepro.report` (and `granrepro report` where the C++ side hands the folder on to
# it) to exit 2 with one line on stderr naming the file and the field, without a traceback, and
# granrepro.load to raise ResultsError; a symlinked or non-PNG figure is never copied into the
# report, and nothing outside the folder changes.
import hashlib
import json
import os
import shutil
import subprocess
import sys

import h5py
import numpy as np
import pytest

import granrepro
from granrepro.reader import ResultsMismatch, _dump_float, fnv1a64, summary_content_hashes
from granrepro.untrusted import MAX_JSON_DEPTH, json_depth

EXP = "brake-failure"
PYTHON_DIR = os.path.join(os.path.dirname(__file__), "..", "..", "python")


def tree_hash(root) -> str:
    h = hashlib.sha256()
    for d, dirs, files in sorted(os.walk(root)):
        dirs.sort()
        for n in sorted(files):
            p = os.path.join(d, n)
            h.update(os.path.relpath(p, root).encode() + b"\0")
            with open(p, "rb") as f:
                h.update(f.read())
    return h.hexdigest()


@pytest.fixture
def crafted(quick_out, tmp_path):
    """tmp/results/brake-failure (a copy of the quick run), tmp/sentinel/ (victim files, hashed) and
    the claims file as `granrepro report` would hand it over, from the untouched copy."""
    results = tmp_path / "results"
    shutil.copytree(os.path.join(quick_out, EXP), results / EXP, ignore=shutil.ignore_patterns("report"))
    sentinel = tmp_path / "sentinel"
    sentinel.mkdir()
    (sentinel / "secret.txt").write_text("the victim's secret\n")
    shutil.copy(results / EXP / "schaefer95-fig3.png", sentinel / "other.png")
    with open(results / EXP / "summary.json") as f:
        s = json.load(f)
    claims = {"experiments": [{"name": EXP, "paper": "", "description": "", "has_results": True, "scale": s["scale"],
                               "notes": [], "claims": s["claims"],
                               "figures": [{"id": "schaefer95-fig3", "caption": "ours"}]}]}
    (tmp_path / "claims.json").write_text(json.dumps(claims))

    class Crafted:
        root, dir, h5, summary = tmp_path, results / EXP, results / EXP / "data.h5", results / EXP / "summary.json"
        claims_file, to = tmp_path / "claims.json", tmp_path / "report"
        before = tree_hash(sentinel)

        def sentinel_untouched(self):
            return tree_hash(sentinel) == self.before

    Crafted.results, Crafted.sentinel = results, sentinel
    return Crafted()


def python_report(c, claims=None):
    env = dict(os.environ, PYTHONPATH=PYTHON_DIR)
    return subprocess.run([sys.executable, "-m", "granrepro.report", "--results", str(c.results), "--claims",
                           str(claims or c.claims_file), "--to", str(c.to)], capture_output=True, text=True, env=env,
                          timeout=120)


def binary_report(binary, c):
    return subprocess.run([binary, "report", "--out", str(c.results), "--to", str(c.to)], capture_output=True,
                          text=True, timeout=120)


def expect_refusal(r, *parts):
    assert r.returncode == 2, (r.returncode, r.stderr)
    assert r.stderr.count("\n") == 1 and "Traceback" not in r.stderr, r.stderr
    for p in parts:
        assert p in r.stderr, (p, r.stderr)


def expect_nothing_written(c):
    assert not c.to.exists() and c.sentinel_untouched()
    assert [n for n in os.listdir(c.root) if n.startswith(".report.")] == []


# ---------------------------------------------------------------- data.h5 edited on one side


def non_utf8_provenance(c):
    with h5py.File(c.h5, "r+") as f:
        f["provenance"].attrs.create("command_line", np.bytes_(b"granrepro \xff\xfe brake-failure"))
    return "attribute 'command_line' of /provenance is not UTF-8"


def parameters_deleted(c):
    with h5py.File(c.h5, "r+") as f:
        del f["parameters"]
    return "has no /parameters"


def k_n_as_text(c):
    with h5py.File(c.h5, "r+") as f:
        del f["parameters/k_N"]
        f["parameters"].create_dataset("k_N", data=np.bytes_(b"2000"))
    return "/parameters/k_N is text"


def k_n_edited(c):
    with h5py.File(c.h5, "r+") as f:
        f["parameters/k_N"][()] = 3000.0
    return "/parameters/k_N is 3000.0 but summary.json beside it has 2000.0"


def truncated(c):
    size = os.path.getsize(c.h5)
    with open(c.h5, "r+b") as f:
        f.truncate(size // 2)
    return "not a readable HDF5 file (truncated or damaged"


# The C++ side (check's verification) lets these through to the Python report: both must refuse.
HANDED_ON = [non_utf8_provenance, parameters_deleted, k_n_as_text, k_n_edited, truncated]


def array_scale(c):
    with h5py.File(c.h5, "r+") as f:
        del f.attrs["scale"]
        f.attrs.create("scale", np.array([b"quick"] * 100000, dtype=h5py.string_dtype("utf-8", 5)))
    return "attribute 'scale' of / is an array of 100000 values"


def vl_array_scale(c):
    with h5py.File(c.h5, "r+") as f:
        del f.attrs["scale"]
        f.attrs.create("scale", np.array(["quick", "quick"], dtype=h5py.string_dtype("utf-8")))
    return "attribute 'scale' of / is an array of 2 values"


def array_parameter_source(c):
    with h5py.File(c.h5, "r+") as f:
        f["parameters"].attrs.create("k_N.source", np.array([b"x"] * 10, dtype=h5py.string_dtype("utf-8", 1)))
    return "attribute 'k_N.source' of /parameters is an array of 10 values"


def scalar_as_array(c):
    with h5py.File(c.h5, "r+") as f:
        name = next(iter(f["scalars"]))
        del f["scalars"][name]
        f["scalars"].create_dataset(name, data=np.zeros(3))
    return "holds 3 values; a scalar is one float64"


# Crashes of the C++ readers on this branch (issue 40 §1, another part): refused by Python alone.
PYTHON_ONLY = [array_scale, vl_array_scale, array_parameter_source, scalar_as_array]


@pytest.mark.parametrize("edit", HANDED_ON + PYTHON_ONLY, ids=lambda e: e.__name__)
def test_a_crafted_data_h5_is_refused_by_the_python_report_and_the_reader(crafted, edit):
    part = edit(crafted)
    expect_refusal(python_report(crafted), str(crafted.h5), part)
    expect_nothing_written(crafted)
    with pytest.raises(granrepro.ResultsError, match="data.h5: "):
        granrepro.load(str(crafted.dir))


@pytest.mark.parametrize("edit", HANDED_ON, ids=lambda e: e.__name__)
def test_a_crafted_data_h5_is_refused_by_granrepro_report(binary, crafted, edit):
    edit(crafted)
    expect_refusal(binary_report(binary, crafted), "data.h5")
    expect_nothing_written(crafted)


def vl_scale(c, value):
    with h5py.File(c.h5, "r+") as f:
        del f.attrs["scale"]
        f.attrs["scale"] = value  # h5py's default: a variable-length UTF-8 string
        assert f.attrs.get_id("scale").get_type().is_variable_str()


def check(binary, c):
    return subprocess.run([binary, "check", EXP, "--out", str(c.results)], capture_output=True, text=True, timeout=120)


def test_a_variable_length_string_is_read_as_its_value_as_the_cpp_readers_read_it(binary, crafted):
    # h5py writes a str attribute as a variable-length string: `granrepro check` reads it as its
    # value, and so does Python, the report and load() (issue 41): the same value is accepted ...
    vl_scale(crafted, "quick")
    r = check(binary, crafted)
    assert r.returncode == 0 and "brake-failure (quick scale)" in r.stdout, r.stderr
    assert granrepro.load(str(crafted.dir)).scale == "quick"
    r = python_report(crafted)
    assert r.returncode == 0 and "Traceback" not in r.stderr, r.stderr
    # ... and another value is the same mismatch on both sides
    shutil.rmtree(crafted.to)
    vl_scale(crafted, "paper")
    r = check(binary, crafted)
    assert r.returncode == 2 and "'scale' is \"quick\" but data.h5 beside it has \"paper\"" in r.stderr, r.stderr
    with pytest.raises(ResultsMismatch, match="'scale' is 'paper' but summary.json beside it has 'quick'"):
        granrepro.load(str(crafted.dir))
    expect_refusal(python_report(crafted), str(crafted.h5), "'scale' is 'paper'")
    expect_nothing_written(crafted)


def test_a_variable_length_string_that_is_not_utf8_is_refused(crafted):
    with h5py.File(crafted.h5, "r+") as f:
        f["provenance"].attrs.create("command_line", np.array(b"granrepro \xff brake-failure",
                                                              dtype=h5py.string_dtype("utf-8")))
        assert f["provenance"].attrs.get_id("command_line").get_type().is_variable_str()
    expect_refusal(python_report(crafted), str(crafted.h5), "attribute 'command_line' of /provenance is not UTF-8")


def test_an_edited_parameter_is_a_mismatch_not_a_value(crafted):
    k_n_edited(crafted)
    with pytest.raises(ResultsMismatch, match=r"/parameters/k_N is 3000.0 but summary.json beside it has 2000.0"):
        granrepro.load(str(crafted.dir))


def test_a_parameter_edited_in_both_files_differs_from_the_summary_hash(crafted):
    k_n_edited(crafted)
    s = json.loads(crafted.summary.read_text())
    s["parameters"]["k_N"]["value"] = 3000.0
    crafted.summary.write_text(json.dumps(s, indent=1))
    with pytest.raises(ResultsMismatch, match="summary.json: content differs from the hash data.h5 beside it recorded"):
        granrepro.load(str(crafted.dir))
    expect_refusal(python_report(crafted), str(crafted.summary), "content differs")


def respelled(v) -> str:
    """JSON of v with keys in reverse order and every real as 17 digits with an exponent."""
    if isinstance(v, dict):
        return "{\n" + ",\n".join(f"{json.dumps(k)}: {respelled(x)}" for k, x in reversed(list(v.items()))) + "}"
    if isinstance(v, list):
        return "[" + ", ".join(respelled(x) for x in v) + "]"
    return f"{v:.16e}" if isinstance(v, float) else json.dumps(v)


def test_a_reformatted_summary_is_the_same_content(crafted):
    # the hash covers values, not the file's layout, key order or number spelling
    text = respelled(json.loads(crafted.summary.read_text()))
    assert "e+03" in text
    crafted.summary.write_text(text)
    granrepro.load(str(crafted.dir))


# A double (as repr() spells it) and the text nlohmann::json(x).dump() writes for it (nlohmann 3's Grisu2,
# checked with a C++ program). From "not the shortest" on the two differ: dump() has one more digit, another
# last digit, or a short decimal written long; a _dump_float from repr()'s digits fails each of those.
DUMPED = [
    (0.0, '0.0'),
    (-0.0, '-0.0'),
    (1.0, '1.0'),
    (-1.0, '-1.0'),
    (0.1, '0.1'),
    (0.5, '0.5'),
    (-2.5, '-2.5'),
    (100.0, '100.0'),
    (2000.0, '2000.0'),
    (0.3333333333333333, '0.3333333333333333'),
    (3.141592653589793, '3.141592653589793'),
    (123456789012345.0, '123456789012345.0'),
    (999999999999999.0, '999999999999999.0'),
    (1000000000000000.0, '1e+15'),
    (1234567890123456.0, '1.234567890123456e+15'),
    (1e+16, '1e+16'),
    (9007199254740992.0, '9.007199254740992e+15'),
    (1e+21, '1e+21'),
    (1e+100, '1e+100'),
    (0.001, '0.001'),
    (0.0001, '0.0001'),
    (1e-05, '1e-05'),
    (1.5e-05, '1.5e-05'),
    (1e-100, '1e-100'),
    (5e-324, '5e-324'),
    (2.2250738585072014e-308, '2.2250738585072014e-308'),
    (1.7976931348623157e+308, '1.7976931348623157e+308'),
    (-1.7976931348623157e+308, '-1.7976931348623157e+308'),
    (float("nan"), 'null'),
    (float("inf"), 'null'),
    (float("-inf"), 'null'),
    # not the shortest
    (127517.56889265165, '127517.56889265164'),
    (571457382358860.2, '571457382358860.3'),
    (1861860846372673.2, '1.8618608463726733e+15'),
    (1.8878486927890702e+60, '1.8878486927890703e+60'),
    (40172.44795702591, '40172.447957025906'),
    (0.521064938508844, '0.5210649385088441'),
    (0.004813756000227615, '0.0048137560002276154'),
    (3108854.610733554, '3108854.6107335538'),
    (11935227.33656877, '11935227.336568771'),
    (3.549141373534213e-247, '3.5491413735342133e-247'),
    (8.463492815240205e-196, '8.4634928152402045e-196'),
    (3.290699758849283e+16, '3.2906997588492832e+16'),
    (1.865717948373117e+16, '1.8657179483731168e+16'),
    (8.6189352642079e+16, '8.618935264207901e+16'),
    (5.78959828081931e+16, '5.7895982808193104e+16'),
    (5.66283e+20, '5.6628300000000003e+20'),
    (3.55194207e+19, '3.5519420700000002e+19'),
    (4.73711e+20, '4.7371100000000003e+20'),
    (2.947612506e-06, '2.9476125059999998e-06'),
    (7.4382777e-06, '7.4382776999999996e-06'),
    (1.894975842637912e-308, '1.8949758426379118e-308'),
    (6.98234620640639e-309, '6.982346206406388e-309'),
]


@pytest.mark.parametrize("x, text", DUMPED, ids=[t for _, t in DUMPED])
def test_a_double_is_written_as_nlohmanns_dump_writes_it(x, text):
    assert _dump_float(x) == text


def test_a_reformatted_summary_of_grisu2_doubles_is_the_same_content():
    # the same as test_a_reformatted_summary_is_the_same_content, for every double above
    finite = [(x, t) for x, t in DUMPED if t != "null"]
    dumped = '{"a":[' + ",".join(t for _, t in finite) + '],"b":"\u00e9"}'
    text = respelled({"b": "\u00e9", "a": [x for x, _ in finite]})
    assert fnv1a64(dumped.encode()) in summary_content_hashes(json.loads(text), text)


def test_an_edited_table_or_scalar_differs_from_its_hash(crafted):
    with h5py.File(crafted.h5, "r+") as f:
        col = f["tables/fig3/dvy"]
        col[0] = col[0] + 1.0
    with pytest.raises(ResultsMismatch, match="table 'fig3' differs from the hash"):
        granrepro.load(str(crafted.dir))
    granrepro.load(str(crafted.dir), tables=["fig4"])  # a table not read is not vouched for
    with h5py.File(crafted.h5, "r+") as f:
        col = f["tables/fig3/dvy"]
        col[0] = col[0] - 1.0
        f.attrs["paper"] = np.bytes_(b"edited, not covered")
        name = next(iter(f["scalars"]))
        f["scalars"][name][()] = 12345.0
    with pytest.raises(ResultsMismatch, match=f"/scalars/{name} is 12345.0 but summary.json"):
        granrepro.load(str(crafted.dir))


def test_edited_points_differ_from_their_hash(crafted):
    with h5py.File(crafted.h5, "r+") as f:
        records = bytes(f["points/records"][()]).replace(b'"resumed":false', b'"resumed":true ', 1)
        del f["points/records"]
        f["points"].create_dataset("records", data=np.frombuffer(records, dtype=np.uint8))
    with pytest.raises(ResultsMismatch, match=r"stored sweep points \(/points\) differ"):
        granrepro.load(str(crafted.dir))
    assert granrepro.load(str(crafted.dir), points=False).points == []


# ---------------------------------------------------------------- summary.json and the claims file


def test_a_deep_or_unreadable_summary_is_refused(crafted):
    s = str(crafted.summary)
    os.remove(s)
    with open(s, "w") as f:
        f.write("[" * 100000 + "]" * 100000)
    expect_refusal(python_report(crafted), s, f"JSON nested deeper than {MAX_JSON_DEPTH} levels")
    with open(s, "wb") as f:
        f.write(b'{"schema": "granrepro-summary", "x": "\xff"}')
    expect_refusal(python_report(crafted), s, "not UTF-8 text")
    os.remove(s)
    os.symlink("/dev/zero", s)
    expect_refusal(python_report(crafted), s, "summary.json is a symbolic link")
    os.remove(s)
    os.mkfifo(s)  # must not block: O_NONBLOCK, then refused as no regular file
    expect_refusal(python_report(crafted), s, "summary.json is a FIFO")
    os.remove(s)
    with open(s, "wb") as f:
        f.truncate((64 << 20) + 1)
    expect_refusal(python_report(crafted), s, "larger than its cap of 64 MiB")
    expect_nothing_written(crafted)


def test_a_symlinked_data_h5_is_refused(crafted):
    elsewhere = crafted.root / "elsewhere"
    elsewhere.mkdir()
    os.rename(crafted.h5, elsewhere / "data.h5")
    os.symlink(elsewhere / "data.h5", crafted.h5)
    expect_refusal(python_report(crafted), "data.h5 is a symbolic link")
    expect_nothing_written(crafted)


def test_a_crafted_claims_file_is_refused(crafted):
    bad = crafted.root / "bad.json"
    bad.write_text("{" * 50000 + "}" * 50000)
    expect_refusal(python_report(crafted, bad), "--claims", "nested deeper")
    judged = json.loads(crafted.claims_file.read_text())
    for change, field in ((("name", "../../escape"), "experiments[0].name"),
                          (("figures", [{"id": "../x", "caption": ""}]), "experiments[0].figures[0].id"),
                          (("claims", [{"id": 5}]), "experiments[0].claims[0].id"),
                          (("notes", "not a list"), "experiments[0].notes"),
                          (("claims", [{"id": "x", "role": "<b>"}]), "experiments[0].claims[0].role"),
                          (("headline", [{"paper": "p", "statements": -1}]), "experiments[0].headline[0].statements"),
                          (("headline", [{"paper": "p", "statements": 1, "reproduced": 1, "deviate": 0, "fail": 0,
                                          "status": {"closed": 1}, "other": {}, "other_verdicts": {}}]),
                           "experiments[0].headline[0].status names 'closed'")):
        j = json.loads(json.dumps(judged))
        j["experiments"][0][change[0]] = change[1]
        bad.write_text(json.dumps(j))
        expect_refusal(python_report(crafted, bad), "--claims", field)
    expect_nothing_written(crafted)


def test_json_depth_counts_brackets_outside_strings():
    assert json_depth('{"a": [1, {"b": "[[[[{{{"}]}') == 3
    assert json_depth('["\\"[[["]') == 1 and json_depth("3") == 0


# ---------------------------------------------------------------- figures (issue 40 §2)


@pytest.mark.parametrize("how", ["symlink_to_secret", "symlink_to_png", "not_a_png"])
def test_a_figure_that_is_not_a_regular_png_is_never_copied(binary, crafted, how):
    png = crafted.dir / "schaefer95-fig3.png"
    os.remove(png)
    if how == "symlink_to_secret":
        os.symlink(crafted.sentinel / "secret.txt", png)
    elif how == "symlink_to_png":
        os.symlink(crafted.sentinel / "other.png", png)
    else:
        png.write_text("the victim's secret\n")
    r = binary_report(binary, crafted)
    assert r.returncode == 0 and "Traceback" not in r.stderr, r.stderr
    assert "schaefer95-fig3" in r.stderr and "not a PNG file" in r.stderr, r.stderr
    assert not (crafted.to / "figures" / "schaefer95-fig3.png").exists()
    for d, _, files in os.walk(crafted.to):
        for n in files:
            with open(os.path.join(d, n), "rb") as f:
                assert b"the victim's secret" not in f.read(), n
    page = (crafted.to / f"{EXP}.html").read_text()
    assert "missing-figure" in page and "not a PNG file" in page
    assert crafted.sentinel_untouched()


def test_a_regular_png_is_copied(binary, crafted):
    r = binary_report(binary, crafted)
    assert r.returncode == 0, r.stderr
    with open(crafted.to / "figures" / "schaefer95-fig3.png", "rb") as f:
        assert f.read(8) == b"\x89PNG\r\n\x1a\n"
