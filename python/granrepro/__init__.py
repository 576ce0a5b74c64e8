"""Read granrepro results (docs/schema.md) into Python, plot them, and make the HTML report.

    import granrepro
    run = granrepro.load("out/brake-failure")
    t = run.tables["fig3"]; v, dv = t["vy_i"], t["dvy"]   # numpy arrays; t.units["dvy"] == "m/s"
    granrepro.plot(run, "fig3")                           # matplotlib Axes, units on the axes

granrepro.load and granrepro.plot need h5py and numpy (and matplotlib for plot);
`python3 -m granrepro.report` (what `granrepro report` runs) also needs jinja2. They are imported
when first used (PEP 562), so a missing one is reported by what needs it, in one line.
load() verifies data.h5 against summary.json and raises granrepro.ResultsError (one line naming
the file and field; ResultsMismatch where the two disagree) on a damaged or edited folder.
"""
_READER = ("load", "Run", "Table", "Quantity", "SCHEMA", "SCHEMA_VERSION", "READS_VERSIONS", "ResultsMismatch")
__all__ = [*_READER, "ResultsError", "plot"]


def __getattr__(name):
    if name in _READER:
        from . import reader
        return getattr(reader, name)
    if name == "ResultsError":  # without h5py: the report catches it before it reads anything
        from .untrusted import ResultsError
        return ResultsError
    if name == "plot":
        from .plotting import plot
        return plot
    raise AttributeError(f"module 'granrepro' has no attribute {name!r}")
