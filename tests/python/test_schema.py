# docs/schema.md names every group, dataset path and attribute the writer emits: checked over the
# data.h5 files of a quick run of brake-failure and emergency-brake and, when ctest passes
# GRANREPRO_SCHEMA_DIRS (the repro runs of every experiment), over those too.
import glob
import os
import re

import h5py
import pytest

DOC = os.path.join(os.path.dirname(__file__), "..", "..", "docs", "schema.md")


def documented():
    """(paths, attributes): regexes from the first column of the data.h5 tables of the document."""
    text = open(DOC).read()
    text = text[text.index("## data.h5"):text.index("## summary.json")]
    paths, attrs = [], []
    for line in text.splitlines():
        m = re.match(r"\| `([^`]+)` \|", line)
        if not m:
            continue
        name = m.group(1)
        pattern = "".join("[^/]+" if part.startswith("<") else re.escape(part)
                          for part in re.split(r"(<[^>]+>)", name))
        (paths if name.startswith("/") else attrs).append(re.compile(pattern))
    return paths, attrs


def emitted(path):
    """Every (object path, attribute name) in the file, and every object path."""
    objects, attributes = ["/"], [("/", a) for a in h5py.File(path, "r").attrs]
    with h5py.File(path, "r") as f:
        def visit(name, obj):
            objects.append("/" + name)
            attributes.extend(("/" + name, a) for a in obj.attrs)
        f.visititems(visit)
    return objects, attributes


def files(quick_out):
    found = sorted(glob.glob(os.path.join(quick_out, "*", "data.h5")))
    for d in filter(None, os.environ.get("GRANREPRO_SCHEMA_DIRS", "").split(os.pathsep)):
        found += sorted(glob.glob(os.path.join(d, "*", "data.h5")))
    return found


def test_every_group_dataset_and_attribute_is_documented(quick_out):
    paths, attrs = documented()
    assert len(paths) >= 8 and len(attrs) >= 20, "the document's tables were not found"
    checked = 0
    for f in files(quick_out):
        objects, attributes = emitted(f)
        for o in objects:
            assert any(p.fullmatch(o) for p in paths), f"{f}: {o} is not in docs/schema.md"
        for o, a in attributes:
            # A name that is a placeholder only (`<parameter>`, `<parameter>.source`: text
            # parameters) is allowed on /parameters alone.
            allowed = [p for p in attrs if o == "/parameters" or not p.pattern.startswith("[^/]+")]
            assert any(p.fullmatch(a) for p in allowed), f"{f}: attribute {a} of {o} is not in docs/schema.md"
        checked += 1
    assert checked >= 2


def test_the_documented_root_attributes_are_there(quick_out):
    with h5py.File(os.path.join(quick_out, "brake-failure", "data.h5"), "r") as f:
        for a in ("schema", "schema_version", "experiment", "paper", "scale", "seed", "code_version",
                  "wall_time_s", "threads", "created_utc", "experiment_file", "summary_json_hash"):
            assert a in f.attrs, a
        for a in ("command_line", "overridden_parameters", "version_compiler", "version_hdf5",
                  "version_fftw", "version_gsl", "expected_file"):
            assert a in f["provenance"].attrs, a
