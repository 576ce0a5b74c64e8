"""Read granrepro results (docs/schema.md) into Python, plot them, and make the HTML report.

    import granrepro
    run = granrepro.load("out/brake-failure")
    t = run.tables["fig3"]; v, dv = t["vy_i"], t["dvy"]   # numpy arrays; t.units["dvy"] == "m/s"
    granrepro.plot(run, "fig3")                           # matplotlib Axes, units on the axes

granrepro.load and granrepro.plot need h5py and numpy (and matplotlib for plot);
`python3 -m granrepro.report` (what `granrepro report` runs) also needs jinja2.
"""
from .reader import (READS_VERSIONS, SCHEMA, SCHEMA_VERSION, Quantity, Run, Table,  # noqa: F401
                     load)
from .plotting import plot  # noqa: F401

__all__ = ["load", "plot", "Run", "Table", "Quantity", "SCHEMA", "SCHEMA_VERSION", "READS_VERSIONS"]
