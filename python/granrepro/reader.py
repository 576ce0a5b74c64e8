"""granrepro.load: reads granrepro results (docs/schema.md) into Python with h5py + numpy
(Debian python3-h5py, python3-numpy)."""
from __future__ import annotations

import json
import os
from dataclasses import dataclass, field

import h5py
import numpy as np

SCHEMA = "granrepro-result"
SCHEMA_VERSION = 3  # the version this reader's writer emits
# 1: before the content hashes (summary_json_hash, data_h5_hash); 2: before the stored sweep
# points (/points) and the whole run's totals (total_wall_time_s, total_cpu_time_s)
READS_VERSIONS = (1, 2, 3)


class Table(dict):
    """The columns of one table, in the writer's order: name -> 1-D numpy array.
    .units: name -> unit; .description: one line; .x: name of the first column (the dimension
    scale of the others)."""

    def __init__(self, name: str, description: str = ""):
        super().__init__()
        self.name = name
        self.description = description
        self.units: dict[str, str] = {}

    @property
    def x(self) -> str:
        return next(iter(self))

    def label(self, column: str) -> str:
        """'v_y_i [m/s]': the column with its unit, for an axis label."""
        return f"{column} [{self.units.get(column, '?')}]"


@dataclass
class Quantity:
    value: object  # float, int, bool, str or numpy array
    unit: str = ""
    description: str = ""
    source: str = ""


@dataclass
class Run:
    path: str
    experiment: str
    scale: str
    seed: int
    attributes: dict
    tables: dict[str, Table] = field(default_factory=dict)
    scalars: dict[str, Quantity] = field(default_factory=dict)
    parameters: dict[str, Quantity] = field(default_factory=dict)
    claims: list[dict] = field(default_factory=list)
    provenance: dict = field(default_factory=dict)
    # Schema 3: every sweep point (data.h5 /points/records): dicts with "sweep", "point",
    # "inputs" (fingerprint), "resumed", "persisted", "cost" {cpu_s, wall_s, started_unix, part,
    # rank} and "outcome" (the point's JSON). Empty for files written before schema 3.
    points: list[dict] = field(default_factory=list)

    def value(self, scalar: str) -> float:
        return self.scalars[scalar].value


def _text(v) -> str:
    return v.decode() if isinstance(v, bytes) else str(v)


def _in_creation_order(group: h5py.Group) -> list[str]:
    """Link names in the order they were created (the writer tracks it); name order otherwise."""
    names = []
    try:
        gid = group.id
        idx = h5py.h5.INDEX_CRT_ORDER
        for i in range(gid.get_num_objs()):
            names.append(gid.links.get_name_by_idx(i, index_type=idx).decode())
        return names
    except Exception:
        return list(group.keys())


def _attrs(obj) -> dict:
    out = {}
    for k, v in obj.attrs.items():
        if isinstance(v, bytes):
            v = v.decode()
        elif isinstance(v, np.generic):
            v = v.item()
        out[k] = v
    return out


def load(out_dir: str, tables=None) -> Run:
    """Reads OUT/<experiment>/ (the folder holding data.h5 and summary.json). tables: the names of
    the tables to read (default: every one); parameters, scalars and provenance are always read."""
    h5_path = os.path.join(out_dir, "data.h5")
    with h5py.File(h5_path, "r") as f:
        root = _attrs(f)
        if root.get("schema") != SCHEMA:
            raise ValueError(f"{h5_path}: not a {SCHEMA} file (schema: {root.get('schema')!r})")
        if root.get("schema_version") not in READS_VERSIONS:
            raise ValueError(f"{h5_path}: schema_version {root.get('schema_version')}, this reader knows {READS_VERSIONS}")
        run = Run(path=out_dir, experiment=root["experiment"], scale=root["scale"], seed=int(root["seed"]),
                  attributes=root)
        pg = f["parameters"]
        pattrs = _attrs(pg)
        for name in _in_creation_order(pg):
            ds = pg[name]
            v = ds[()]
            if ds.shape == ():
                v = v.item()
                if ds.dtype == np.uint8:
                    v = bool(v)
            a = _attrs(ds)
            run.parameters[name] = Quantity(v, a.get("unit", ""), a.get("description", ""),
                                            pattrs.get(name + ".source", ""))
        for k, v in pattrs.items():  # text parameters
            if not k.endswith(".source"):
                run.parameters[k] = Quantity(v, "", "", pattrs.get(k + ".source", ""))
        sg = f["scalars"]
        for name in _in_creation_order(sg):
            ds = sg[name]
            a = _attrs(ds)
            run.scalars[name] = Quantity(float(np.asarray(ds[()]).reshape(-1)[0]), a.get("unit", ""),
                                         a.get("description", ""))
        tg = f["tables"]
        for tname in _in_creation_order(tg):
            if tables is not None and tname not in tables:
                continue
            g = tg[tname]
            t = Table(tname, _text(g.attrs.get("description", "")))
            for c in _in_creation_order(g):
                t[c] = g[c][()]
                t.units[c] = _text(g[c].attrs.get("unit", ""))
            run.tables[tname] = t
        if "provenance" in f:
            run.provenance = _attrs(f["provenance"])
        if "points" in f:
            run.points = json.loads(bytes(f["points"]["records"][()]).decode())
    summary = os.path.join(out_dir, "summary.json")
    if os.path.exists(summary):
        with open(summary) as s:
            run.claims = json.load(s).get("claims", [])
    return run
