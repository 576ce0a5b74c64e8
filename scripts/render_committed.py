#!/usr/bin/env python3
"""Re-render the committed paper-scale figures from paper_figures/<experiment>/ (issue 41).

paper_figures/<experiment>/ holds only the compact data.h5 and summary.json of the paper-scale run
(`granrepro export`); the tables/*.tsv the plot scripts read are not committed. This script makes
a temporary results folder TMP/<experiment>/ from them:

  summary.json, data.h5   copied as they are;
  tables/<table>.tsv      written from data.h5's /tables/<table>/<column> datasets in the format of
                          docs/schema.md "tables/<table>.tsv": line 1 the column names
                          (tab-separated, in the writer's creation order), line 2
                          "# [unit]\t[unit]...", then one row per value, NaN where a shorter
                          column has ended or a value is not finite;

runs `granrepro plot <experiment> --out TMP` (an argument list, no shell) and copies the PNGs it
drew over paper_figures/<figure-id>.png (paper_figures/ holds no PDFs, so none are copied).

Numbers: written as granrepro's own writer writes them (C++ ostream with setprecision(10), i.e.
"%.10g", src/io/result_writer.cpp write_tables_tsv), so the scripts read the text `granrepro plot`
read in the original run folder; --exact writes repr() instead (each reads back to the double
data.h5 holds). With unchanged scripts (GRANREPRO_HOME at d9a578f, whose plots/ are those of
9020117 that drew them) and --check, the default drew all 16 figures that the compact copies can
draw byte-identical to the committed PNGs; --exact drew 15 of them byte-identical and Fig. 9 with
4 pixels one level (of 255) apart (anti-aliasing of a point whose coordinate differs in the 11th
digit), so the default reproduces the committed figures.

A table that the compact copy left out (root attribute omitted_tables, e.g. cluster-growth's
snapshot_<k> of Fig. 11) cannot be written: a figure that needs it is not drawn (granrepro plot
exits 4 and names it) and its committed PNG is left as it is; the paper-scale run must be redone
for it.

Usage (needs h5py and numpy: Debian python3-h5py, python3-numpy, i.e. /usr/bin/python3):
  python3 scripts/render_committed.py pipe-arching [cluster-growth ...]
      [--bin build/granrepro] [--from paper_figures] [--figure luding98-fig14 ...]
      [--check] [--exact] [--keep]
--figure  copy only these figures (default: every figure drawn);
--check   copy nothing: compare each drawn PNG with the committed one (byte-identical or not) and
          exit 1 if any differs;
--keep    keep the temporary folder (its path is printed).
Exit: 0 done; 1 --check found a difference; 2 bad input (no such folder, a figure not drawn
that --figure asks for, granrepro failed).
"""
import argparse
import filecmp
import json
import math
import os
import shutil
import subprocess
import sys
import tempfile

try:
    import h5py
    import numpy as np
except ImportError as e:  # pragma: no cover - environment
    sys.exit(f"render_committed.py: {e}; install python3-h5py and python3-numpy (run with /usr/bin/python3)")


def _text(v):
    return v.decode() if isinstance(v, bytes) else str(v)


def _in_creation_order(group):
    """Link names in the order the writer created them (the column order of the TSV)."""
    try:
        gid = group.id
        return [gid.links.get_name_by_idx(i, index_type=h5py.h5.INDEX_CRT_ORDER).decode()
                for i in range(gid.get_num_objs())]
    except Exception:  # a file without creation order: name order
        return list(group.keys())


def number(x, exact):
    x = float(x)
    if not math.isfinite(x):
        return "NaN"
    return repr(x) if exact else "%.10g" % x


def write_tables(h5_path, tables_dir, exact):
    """Writes every table of data.h5 as tables/<name>.tsv; returns (written names, omitted text)."""
    os.makedirs(tables_dir, exist_ok=True)
    names = []
    with h5py.File(h5_path, "r") as f:
        omitted = _text(f.attrs.get("omitted_tables", "none"))
        tg = f["tables"]
        for tname in _in_creation_order(tg):
            g = tg[tname]
            cols = _in_creation_order(g)
            values = [np.asarray(g[c][()], dtype=float).reshape(-1) for c in cols]
            units = [_text(g[c].attrs.get("unit", "")) for c in cols]
            rows = max((len(v) for v in values), default=0)
            lines = ["\t".join(cols), "#" + "".join((" [" if i == 0 else "\t[") + u + "]" for i, u in enumerate(units))]
            for r in range(rows):
                lines.append("\t".join(number(v[r], exact) if r < len(v) else "NaN" for v in values))
            with open(os.path.join(tables_dir, tname + ".tsv"), "w", encoding="utf-8") as out:
                out.write("\n".join(lines) + "\n")
            names.append(tname)
    return names, omitted


def render(experiment, args):
    src = os.path.join(args.source, experiment)
    for name in ("summary.json", "data.h5"):
        if not os.path.isfile(os.path.join(src, name)):
            print(f"render_committed.py: {src}/{name} is missing", file=sys.stderr)
            return 2
    with open(os.path.join(src, "summary.json"), encoding="utf-8") as fh:
        if json.load(fh).get("experiment") != experiment:
            print(f"render_committed.py: {src}/summary.json is not of experiment {experiment}", file=sys.stderr)
            return 2
    tmp = tempfile.mkdtemp(prefix="render-committed-")
    try:
        run_dir = os.path.join(tmp, experiment)
        os.makedirs(run_dir)
        for name in ("summary.json", "data.h5"):
            shutil.copyfile(os.path.join(src, name), os.path.join(run_dir, name))
        names, omitted = write_tables(os.path.join(run_dir, "data.h5"), os.path.join(run_dir, "tables"), args.exact)
        print(f"{experiment}: {len(names)} tables written; left out of the compact copy: {omitted}")
        proc = subprocess.run([args.bin, "plot", experiment, "--out", tmp], capture_output=True, text=True)
        for line in (proc.stdout + proc.stderr).splitlines():
            print(f"  granrepro: {line}")
        if proc.returncode not in (0, 4):  # 4: a figure was not drawn (named above)
            print(f"render_committed.py: granrepro plot {experiment} exited {proc.returncode}", file=sys.stderr)
            return 2
        drawn = sorted(n[:-4] for n in os.listdir(run_dir) if n.endswith(".png"))
        wanted = args.figure or drawn
        status = 0
        for fid in wanted:
            png = os.path.join(run_dir, fid + ".png")
            if fid not in drawn:
                if args.figure:  # asked for by name: not drawn is an error
                    print(f"render_committed.py: {fid} was not drawn (see granrepro's words above)", file=sys.stderr)
                    status = 2
                continue
            committed = os.path.join(args.source, fid + ".png")
            if args.check:
                same = os.path.isfile(committed) and filecmp.cmp(png, committed, shallow=False)
                print(f"  {fid}.png: {'byte-identical to' if same else 'DIFFERS from'} {committed}")
                status = status or (0 if same else 1)
            else:
                shutil.copyfile(png, committed)
                print(f"  {fid}.png -> {committed}")
        return status
    finally:
        if args.keep:
            print(f"  kept {tmp}")
        else:
            shutil.rmtree(tmp, ignore_errors=True)


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("experiments", nargs="+")
    p.add_argument("--bin", default=os.path.join("build", "granrepro"))
    p.add_argument("--from", dest="source", default="paper_figures")
    p.add_argument("--figure", action="append", help="copy only this figure (repeatable)")
    p.add_argument("--check", action="store_true", help="compare with the committed PNGs, copy nothing")
    p.add_argument("--exact", action="store_true", help="write repr() numbers, not granrepro's %%.10g")
    p.add_argument("--keep", action="store_true", help="keep the temporary folder")
    args = p.parse_args()
    status = 0
    for e in args.experiments:
        status = max(status, render(e, args))
    return status


if __name__ == "__main__":
    sys.exit(main())
