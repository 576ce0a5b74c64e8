# python/granrepro.py against a quick-scale run: what load() returns must be what the binary
# wrote (summary.json, the TSV tables) and what the schema promises (types, units, provenance).
import csv
import json
import math
import os

import numpy as np

import granrepro


def tsv(path):
    with open(path) as f:
        lines = [l for l in f if not l.startswith("#")]
    rows = list(csv.reader(lines, delimiter="\t"))
    return rows[0], [[float(v) for v in r] for r in rows[1:]]


def test_tables_scalars_and_units_match_what_was_written(quick_out):
    run = granrepro.load(os.path.join(quick_out, "brake-failure"))
    assert run.experiment == "brake-failure" and run.scale == "quick" and run.seed == 1
    fig3 = run.tables["fig3"]
    # Columns in the experiment's order, the first one the x axis, with units.
    assert list(fig3)[:3] == ["vy_i", "dvy", "dvx"]
    assert fig3.x == "vy_i" and fig3.units["dvy"] == "m/s"
    head, rows = tsv(os.path.join(quick_out, "brake-failure", "tables", "fig3.tsv"))
    assert head == list(fig3)
    np.testing.assert_allclose(fig3["dvy"], [r[1] for r in rows], rtol=1e-9)
    with open(os.path.join(quick_out, "brake-failure", "summary.json")) as f:
        summary = json.load(f)
    assert set(run.scalars) == set(summary["scalars"])
    for name, q in run.scalars.items():
        expected = summary["scalars"][name]
        assert (math.isnan(q.value) if expected is None else q.value == expected), name
        assert q.unit == summary["units"][name], name
    assert [c["id"] for c in run.claims] == [c["id"] for c in summary["claims"]]


def test_parameters_keep_their_types_and_overrides_are_recorded(quick_out):
    run = granrepro.load(os.path.join(quick_out, "emergency-brake"))
    assert run.seed == 7 and isinstance(run.seed, int)
    p = run.parameters
    assert p["n_positions"].value == 3 and isinstance(p["n_positions"].value, int)
    assert p["n_positions"].unit == "1" and "10 initial positions" in p["n_positions"].source
    assert list(p["vx_list"].value) == [0.1, 0.3, 0.5] and p["vx_list"].unit == "m/s"
    prov = run.provenance
    assert prov["overridden_parameters"] == "n_positions=3"
    assert "--set n_positions=3" in prov["command_line"]
    assert prov["version_hdf5"].count(".") == 2 and prov["version_gsl"] and prov["version_fftw"].startswith("fftw")
    assert "[[claim]]" in prov["expected_file"] or "claim" in prov["expected_file"]
    assert any(k.startswith("plot_schaefer95-fig") for k in prov)


def test_scalars_are_scalars_and_x_is_a_dimension_scale(quick_out):
    import h5py
    with h5py.File(os.path.join(quick_out, "brake-failure", "data.h5"), "r") as f:
        assert isinstance(f.attrs["seed"], np.unsignedinteger)
        for name, ds in f["scalars"].items():
            assert ds.shape == (), name
        fig3 = f["tables/fig3"]
        assert h5py.h5ds.is_scale(fig3["vy_i"].id)
        assert fig3["dvy"].dims[0][0] == fig3["vy_i"]


def test_plot_draws_the_table_with_units(quick_out, tmp_path):
    import matplotlib
    matplotlib.use("Agg")
    run = granrepro.load(os.path.join(quick_out, "brake-failure"))
    ax = granrepro.plot(run, "fig3", ["dvy", "dvx"], logx=True)
    assert ax.get_xlabel() == "vy_i [m/s]"
    assert len(ax.lines) == 2
    np.testing.assert_array_equal(ax.lines[0].get_ydata(), run.tables["fig3"]["dvy"])
    ax.figure.savefig(tmp_path / "fig3.png")
    assert (tmp_path / "fig3.png").stat().st_size > 1000


def test_a_file_of_another_schema_is_refused(tmp_path):
    import h5py
    import pytest
    with h5py.File(tmp_path / "data.h5", "w") as f:
        f.attrs["schema"] = np.bytes_(b"something-else")  # fixed-length, as granrepro writes text
    with pytest.raises(granrepro.ResultsError, match="not a granrepro-result"):
        granrepro.load(str(tmp_path))
