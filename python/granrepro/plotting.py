"""granrepro.plot: a table of a loaded run drawn with matplotlib (Debian python3-matplotlib)."""
from __future__ import annotations

import os

from .reader import Run


def plot(run: Run, table: str, columns=None, ax=None, logx=False, logy=False, **kwargs):
    """Draws columns (default: all but the first) of run.tables[table] against its first column
    with matplotlib; axis labels carry the units. Returns the Axes."""
    import matplotlib
    if ax is None:
        if not os.environ.get("DISPLAY"):
            matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        _, ax = plt.subplots()
    t = run.tables[table]
    x = t.x
    cols = [c for c in t if c != x] if columns is None else list(columns)
    for c in cols:
        if len(t[c]) != len(t[x]):
            raise ValueError(f"{table}/{c} has {len(t[c])} values, {x} has {len(t[x])}")
        ax.plot(t[x], t[c], label=t.label(c), **kwargs)
    ax.set_xlabel(t.label(x))
    units = {t.units[c] for c in cols}
    ax.set_ylabel(f"[{units.pop()}]" if len(units) == 1 else "")
    ax.set_title(f"{run.experiment}: {table}")
    if logx:
        ax.set_xscale("log")
    if logy:
        ax.set_yscale("log")
    ax.legend()
    return ax
