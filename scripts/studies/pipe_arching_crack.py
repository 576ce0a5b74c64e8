#!/usr/bin/python3
"""Issue 43 §1 (Luding 1998 Sec. 5, Fig. 13: the crack): a local opening at the initiating disk.

Run by scripts/studies/pipe_arching_crack.sh (which makes the runs); reads their data.h5 files
(h5py) and prints the markdown table of the study.

The local opening. The crack of Fig. 13 opens "at the position of the initiating particle (at the
black bar)", i.e. at the first hot wall disk of the first arch (the run's marks table gives its
centre in every snapshot). In a snapshot, a strip of the pipe beside that disk's wall is taken:
  own: the disk's own width, x in [x_i - d/2, x_i + d/2] (clipped at the wall),
  3d:  the first 3 d of the wall, x in [0, 3 d] (measured from the disk's wall).
Every disk that reaches into the strip blocks the heights [y - h, y + h], h its largest half chord
inside the strip (h = d/2 when its centre lies in the strip). The local opening is the longest
height interval that no disk blocks, from the initiating disk's centre down to y_i - DEPTH, and
never below the crack_min_particles-th lowest disk (the spray at the bottom, which the
wall-to-wall detector also ignores): a horizontal channel through the whole strip, surface to
surface, in units of d. The intact lattice (s = 1.01 d) gives 0 in both strips.
Per seed the largest value is taken over the snapshots in [t_arch, t_arch + arch_window] (the
window of the wall-to-wall detector's opening_max_after) and over every snapshot from the first
hot wall disk (t_precursor) to t_end.
"""
import json
import os
import sys
from pathlib import Path

import h5py
import numpy as np

DEPTH = float(os.environ.get("DEPTH", "10"))  # d; 10 = below_depth of experiments/pipe-arching.toml


def records(h5):
    """Per-seed outcomes (the sweep's point records), in seed-index order."""
    recs = json.loads(bytes(h5["points/records"][()]).decode())
    recs.sort(key=lambda r: r["point"])
    return [r["outcome"] for r in recs]


def param(h5, name):
    return h5["parameters"][name][()]


def local_gap(x, y, xi, yi, lo_cut, L, strip):
    """Longest unblocked height interval below (xi, yi) in the strip beside its wall [d]."""
    if xi > 0.5 * L:  # mirror: the disk's wall at x = 0
        x, xi = L - x, L - xi
    if strip == "own":
        a, b = max(0.0, xi - 0.5), xi + 0.5
    else:
        a, b = 0.0, 3.0
    dx = np.where(x < a, a - x, np.where(x > b, x - b, 0.0))
    inside = dx < 0.5
    h = np.sqrt(np.clip(0.25 - dx[inside] ** 2, 0.0, None))
    lo_iv, hi_iv = y[inside] - h, y[inside] + h
    top, bot = yi, max(yi - DEPTH, lo_cut)
    if top <= bot:
        return float("nan")
    order = np.argsort(lo_iv)
    best, cover = 0.0, bot  # sweep upward: cover = highest blocked height so far, from bot
    for k in order:
        l, u = lo_iv[k], hi_iv[k]
        if u <= bot:
            continue
        if l >= top:
            break
        if l > cover:
            best = max(best, min(l, top) - cover)
        cover = max(cover, u)
        if cover >= top:
            break
    if cover < top:
        best = max(best, top - cover)
    return best


def snapshots(h5):
    """(t, x, y) of every snapshot table, by time."""
    out = []
    for name in h5["tables"]:
        if name.startswith("snapshot_t"):
            g = h5["tables"][name]
            out.append((float(name[len("snapshot_t"):]), g["x"][()], g["y"][()]))
    return sorted(out, key=lambda s: s[0])


def local_openings(h5, seed_outcome):
    """Run 0's local openings: {own,3d} x {after,all}, and per snapshot (t, own, 3d, wall-to-wall)."""
    L = float(param(h5, "width"))
    # With wall_jitter (pipe_arching_walls.sh) the right wall is at width + both outward shifts
    # (the left wall stays at x = 0); older runs have no such fields.
    for key in ("wall_left", "wall_right"):
        if seed_outcome.get(key) is not None and np.isfinite(seed_outcome[key]):
            L += seed_outcome[key]
    nmin = int(param(h5, "crack_min_particles"))
    window = float(param(h5, "arch_window"))
    marks = h5["tables/marks"]
    mt = marks["t"][()]
    ix, iy = marks["initiator_x"][()], marks["initiator_y"][()]
    tl = h5["tables/timeline"]
    w2w = dict(zip(np.round(tl["t"][()], 6), tl["opening"][()]))
    t_arch, t_prec = seed_outcome.get("t_arch"), seed_outcome.get("t_precursor")
    res = {"own_after": -1.0, "3d_after": -1.0, "own_all": -1.0, "3d_all": -1.0, "n_after": 0, "rows": [],
           "t_own05": float("nan"), "t_3d05": float("nan")}
    if t_arch is None or t_prec is None:
        return None  # no arch, or no initiating disk: nothing to measure at
    for t, x, y in snapshots(h5):
        k = int(np.argmin(np.abs(mt - t)))
        if abs(mt[k] - t) > 1e-9 or not np.isfinite(ix[k]):
            continue
        lo_cut = np.sort(y)[nmin - 1]
        own = local_gap(x, y, ix[k], iy[k], lo_cut, L, "own")
        d3 = local_gap(x, y, ix[k], iy[k], lo_cut, L, "3d")
        res["rows"].append((t, own, d3, float(w2w.get(round(t, 6), float("nan")))))
        if not np.isfinite(own):
            continue
        if t >= t_prec - 1e-9:
            if own >= 0.5 and not np.isfinite(res["t_own05"]):
                res["t_own05"] = t
            if d3 >= 0.5 and not np.isfinite(res["t_3d05"]):
                res["t_3d05"] = t
            res["own_all"] = max(res["own_all"], own)
            res["3d_all"] = max(res["3d_all"], d3)
        if t_arch - 1e-9 <= t <= t_arch + window + 1e-9:
            res["own_after"] = max(res["own_after"], own)
            res["3d_after"] = max(res["3d_after"], d3)
            res["n_after"] += 1
    for key in ("own_after", "3d_after", "own_all", "3d_all"):
        if res[key] < 0:
            res[key] = float("nan")
    return res


def stats(vals, n_total):
    """median, max, fraction of seeds above 0.3 d and 0.5 d (over n_total seeds; a seed without a
    value counts as below), n with a value."""
    v = np.array([x for x in vals if x is not None and np.isfinite(x)])
    if len(v) == 0:
        return "-", "-", "-", "-", 0
    return (f"{np.median(v):.3f}", f"{v.max():.3f}", f"{np.sum(v > 0.3) / n_total:.2f}",
            f"{np.sum(v > 0.5) / n_total:.2f}", len(v))


def main():
    out = Path(sys.argv[1])
    committed = Path(sys.argv[2])
    configs = sys.argv[3:]
    rows_detector, rows_arch, rows_time, per_seed = [], [], [], []
    stored_note, tsv = [], []
    for cfg in configs:
        # The config's 16-seed run (default: the committed paper-scale run, 32 seeds); a study with
        # frame runs only (pipe_arching_walls.sh, committed = none) has none.
        h5path = committed if cfg == "default" and committed.is_file() else out / cfg / "pipe-arching" / "data.h5"
        seeds = []
        if h5path.is_file():
            with h5py.File(h5path, "r") as h5:
                seeds = records(h5)
                if cfg == "default":  # what the stored results allow: run 0's six snapshots
                    lo = local_openings(h5, seeds[0])
                    if lo:
                        for t, own, d3, w in lo["rows"]:
                            stored_note.append(f"| {t:.3f} | {own:.3f} | {d3:.3f} | {w:.3f} |")
        n = len(seeds)
        if n:
            w_after = [s.get("opening_max_after") for s in seeds]
            w_all = [s.get("opening_max_all") for s in seeds]
            left = np.array([s["arch_left_4ms"] for s in seeds if s.get("arch_left_4ms") is not None])
            arch_n = sum(1 for s in seeds if s.get("t_arch") is not None)
            crack_n = sum(1 for s in seeds if s.get("t_crack") is not None)
            src = "committed paper_figures" if cfg == "default" else "n_seeds=16 run"
            rows_detector.append((cfg, f"wall-to-wall, 10 ms after arch ({src})", n, *stats(w_after, n)))
            rows_detector.append((cfg, f"wall-to-wall, any frame >= 0.01 s ({src})", n, *stats(w_all, n)))
            below = [s.get("opening_below") for s in seeds]
            rows_detector.append((cfg, f"plug separation opening_below ({src})", n, *stats(below, n)))
        # Single-seed runs with every frame as a snapshot.
        singles = sorted((out / cfg / "frames").glob("seed*/pipe-arching/data.h5"))
        loc = {k: [] for k in ("own_after", "3d_after", "own_all", "3d_all")}
        sw_after, lag, by_paper, n_open, left_f = [], [], 0, 0, []
        sw_all, below_f, vbar_f, tarch_f, crack_f = [], [], [], [], 0
        for p in singles:
            with h5py.File(p, "r") as h5:
                s0 = records(h5)[0]
                r = local_openings(h5, s0)
                seed = p.parent.parent.name
                sw_after.append(s0.get("opening_max_after"))
                sw_all.append(s0.get("opening_max_all"))
                below_f.append(s0.get("opening_below"))
                vbar_f.append(s0.get("vbar0"))
                tarch_f.append(s0.get("t_arch"))
                crack_f += s0.get("t_crack") is not None
                if s0.get("arch_left_4ms") is not None:
                    left_f.append(s0["arch_left_4ms"])
                for k in loc:
                    loc[k].append(r[k] if r else None)
                if r and np.isfinite(r["t_own05"]):
                    n_open += 1
                    lag.append(r["t_own05"] - s0["t_arch"])
                    by_paper += r["t_own05"] <= 0.060 + 1e-9
                per_seed.append((cfg, seed, s0.get("t_precursor"), s0.get("t_arch"), s0.get("arch_left_4ms"),
                                 s0.get("opening_max_after"),
                                 *(r[k] if r else float("nan") for k in ("own_after", "3d_after", "own_all", "3d_all"))))
        m = len(singles)
        if m:
            rows_detector.append((cfg, "wall-to-wall, 10 ms after arch (frame runs)", m, *stats(sw_after, m)))
            rows_detector.append((cfg, "wall-to-wall, any frame >= 0.01 s (frame runs)", m, *stats(sw_all, m)))
            rows_detector.append((cfg, "plug separation opening_below (frame runs)", m, *stats(below_f, m)))
            rows_detector.append((cfg, "local own width, 10 ms after arch", m, *stats(loc["own_after"], m)))
            rows_detector.append((cfg, "local 3 d of wall, 10 ms after arch", m, *stats(loc["3d_after"], m)))
            rows_detector.append((cfg, "local own width, t_precursor .. t_end", m, *stats(loc["own_all"], m)))
            rows_detector.append((cfg, "local 3 d of wall, t_precursor .. t_end", m, *stats(loc["3d_all"], m)))
        if m:
            rows_time.append((cfg, m, f"{n_open / m:.2f}", f"{1e3 * np.median(lag):.0f}" if lag else "-",
                              f"{1e3 * min(lag):.0f} .. {1e3 * max(lag):.0f}" if lag else "-",
                              f"{sum(1 for x in lag if x <= 0.004 + 1e-9) / m:.2f}", f"{by_paper / m:.2f}",
                              sum(1 for v in loc["3d_all"] if v is not None and np.isfinite(v) and v >= 0.5)))
        left_f = np.array(left_f)
        if len(left_f):
            rows_arch.append((cfg + " (frame runs)", m, len(left_f), "-", f"{np.median(left_f):.2f}",
                              f"{np.percentile(left_f, 10):.2f}", f"{left_f.min():.2f}", f"{np.mean(left_f <= 0.25):.2f}"))
        if n:
            rows_arch.append((cfg, n, arch_n, crack_n,
                              f"{np.median(left):.2f}" if len(left) else "-",
                              f"{np.percentile(left, 10):.2f}" if len(left) else "-",
                              f"{left.min():.2f}" if len(left) else "-",
                              f"{np.mean(left <= 0.25):.2f}" if len(left) else "-"))
        if m:  # one line per config for the figure (TSV, env TSV): frame runs only
            fin = lambda v: np.array([x for x in v if x is not None and np.isfinite(x)])
            own, wa, vb, ta = fin(loc["own_after"]), fin(sw_after), fin(vbar_f), fin(tarch_f)
            tsv.append((cfg, m, len(left_f), crack_f,
                        np.median(own) if len(own) else np.nan, np.sum(own > 0.3) / m, np.sum(own > 0.5) / m,
                        np.sum(fin(loc["3d_after"]) > 0.3) / m, np.median(wa) if len(wa) else np.nan,
                        wa.max() if len(wa) else np.nan, np.median(left_f) if len(left_f) else np.nan,
                        np.mean(left_f <= 0.25) if len(left_f) else np.nan,
                        np.median(vb) if len(vb) else np.nan, np.median(ta) if len(ta) else np.nan))
    if os.environ.get("TSV"):
        with open(os.environ["TSV"], "w") as f:
            f.write("# pipe_arching_crack.py on the frame runs of each config (scripts/studies/pipe_arching_walls.sh)\n")
            f.write("# index\tconfig\tseeds\tseeds_with_arch\tseeds_with_wall_to_wall_crack\tlocal_own_after_median_d"
                    "\tlocal_own_after_share_gt_0.3\tlocal_own_after_share_gt_0.5\tlocal_3d_after_share_gt_0.3"
                    "\twall_to_wall_after_median_d\twall_to_wall_after_max_d\tarch_left_4ms_median"
                    "\tarch_left_4ms_share_le_0.25\tvbar_t0_median_m_per_s\tt_arch_median_s\n")
            for k, r in enumerate(tsv):
                f.write(f"{k}\t{r[0]}\t{r[1]}\t{r[2]}\t{r[3]}\t" + "\t".join(f"{x:.4f}" for x in r[4:]) + "\n")
    print("| config | detector | seeds | median [d] | max [d] | > 0.3 d | > 0.5 d | seeds with a value |")
    print("|---|---|---|---|---|---|---|---|")
    for r in rows_detector:
        print("| " + " | ".join(str(x) for x in r) + " |")
    print()
    print("| config | seeds | seeds with an arch | seeds with a wall-to-wall crack >= 0.5 d | arch_left_4ms median | 10th pct | min | share <= 0.25 |")
    print("|---|---|---|---|---|---|---|---|")
    for r in rows_arch:
        print("| " + " | ".join(str(x) for x in r) + " |")
    print()
    print("| config | frame runs | share with a local own-width gap >= 0.5 d (t_precursor .. t_end) | its first time minus t_arch, median [ms] | range [ms] | share within 4 ms of the arch | share by 0.060 s (the paper's crack time) | seeds with a 3 d gap >= 0.5 d at any frame |")
    print("|---|---|---|---|---|---|---|---|")
    for r in rows_time:
        print("| " + " | ".join(str(x) for x in r) + " |")
    print()
    if stored_note:
        print("Stored data (committed paper_figures/pipe-arching/data.h5, run 0, its six snapshots):")
        print()
        print("| t [s] | local own [d] | local 3 d [d] | wall-to-wall [d] |")
        print("|---|---|---|---|")
        for line in stored_note:
            print(line)
        print()
    print("Per seed (frame runs): config, seed, t_precursor, t_arch, arch_left_4ms, wall-to-wall after, local own after, local 3 d after, local own all, local 3 d all")
    print()
    print("```")
    for r in per_seed:
        print("\t".join(x if isinstance(x, str) else ("-" if x is None or not np.isfinite(x) else f"{x:.3f}") for x in r))
    print("```")


if __name__ == "__main__":
    main()
