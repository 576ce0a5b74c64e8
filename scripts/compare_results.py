#!/usr/bin/env python3
"""Compare the numbers of two results folders bit for bit: every scalar and every table column of
each experiment's data.h5 (values and units), not provenance, timings or stored points (a point
file's layout may change while the figures stay). Exit 0 if identical, 1 with one line per
difference. Usage: compare_results.py OLD NEW [EXPERIMENT...]"""
import os, sys
import h5py, numpy as np

def leaves(f, group):
    out = {}
    if group not in f: return out
    def visit(name, obj):
        if isinstance(obj, h5py.Dataset):
            out[name] = (np.asarray(obj[()]), obj.attrs.get("unit"))
    f[group].visititems(visit)
    return out

# Timings, as verify's is_timing_name (src/harness/verify.cpp): no rerun reproduces them.
def is_timing(name):
    base = name.rsplit("/", 1)[-1]
    return any(s in base for s in ("wall_seconds", "wall_time", "seconds_per")) or base.endswith("per_second") \
        or base == "resumed_points"

def same(a, b):
    if a.shape != b.shape or a.dtype != b.dtype: return False
    if a.dtype.kind in "fc":
        return a.tobytes() == b.tobytes()
    return np.array_equal(a, b)

old, new = sys.argv[1], sys.argv[2]
names = sys.argv[3:] or sorted(d for d in os.listdir(old) if os.path.isfile(os.path.join(old, d, "data.h5")))
bad = 0
for e in names:
    fo, fn = os.path.join(old, e, "data.h5"), os.path.join(new, e, "data.h5")
    if not os.path.isfile(fn):
        print(f"{e}: no data.h5 in {new}"); bad += 1; continue
    with h5py.File(fo, "r") as a, h5py.File(fn, "r") as b:
        n = 0
        for g in ("scalars", "tables"):
            la, lb = leaves(a, g), leaves(b, g)
            for k in sorted(set(la) | set(lb)):
                if g == "scalars" and is_timing(k): continue
                n += 1
                if k not in la or k not in lb:
                    print(f"{e}: {g}/{k} only in {'old' if k in la else 'new'}"); bad += 1
                elif not same(la[k][0], lb[k][0]) or la[k][1] != lb[k][1]:
                    print(f"{e}: {g}/{k} differs"); bad += 1
    print(f"{e}: {n} datasets compared")
print("identical" if bad == 0 else f"{bad} differences")
sys.exit(1 if bad else 0)
