"""The report: a static site (index.html, one page per experiment, style.css; the figures linked
or copied) of the results in a folder, from the claims `granrepro report` judged against expected/.

    python3 -m granrepro.report --results DIR --claims CLAIMS.json --to REPORTDIR

CLAIMS.json ({"experiments": [{name, description, paper, paper_key, paper_short, paper_citation,
figures: [{id, caption}], smoke, has_results, scale, notes, headline: [...], claims: [...]}]}: each
experiment as `granrepro list --json` prints it, then what its results say; experiments in registry
order (the papers are grouped by paper_key, shown by paper_citation, and label their figures with
paper_short: experiments/<name>.toml is the one place that names them), claims in
summary.json's format with each claim's role and each deviation's status, headline as
headline_json in src/harness/claims.cpp) is written by `granrepro report`, which judges every claim
as `granrepro check` does. The summary page opens with the headline `check --all` prints for the
same folder (the experiments' headlines summed per paper); claims judged before issue 41 (no role,
no headline) are shown with the role "—". Every text is
escaped (Jinja2 autoescape): a results folder is data, never code. The report is written into a
hidden staging folder beside REPORTDIR and switched into place when complete.

A results folder is untrusted input (docs/schema.md, "Trust model"): every file is read through
granrepro.untrusted (no symlinks, size caps, bounded JSON depth) and granrepro.load (data.h5
verified against summary.json); a figure is shown only if it is a regular file that is PNG (or
PDF) by its first bytes, and only such a file is copied. Pages are written only for the
experiments with results; every page names the results folder as --results gave it.

Exit codes: 0 written; 2 bad input (one line naming the file and field, or the parameter): damaged
or edited results, a claims file that is not `granrepro report`'s, a --to that is not a report; 3
not written (the previous report is untouched); 4 jinja2 or h5py missing; 1 an internal error
(one line, never a traceback).
"""
from __future__ import annotations

import argparse
import ctypes
import math
import os
import re
import shutil
import sys
import tomllib
from dataclasses import dataclass, field
from importlib import resources

from ..untrusted import (MAX_IMAGE_BYTES, MAX_SUMMARY_BYTES, PDF_MAGIC, PNG_MAGIC, ResultsError, printable,
                         read_file, read_json)

MARKER = ".granrepro-report"  # in every report folder: only such a folder is ever replaced
MAX_TABLE_ROWS = 60           # rows of a cited table shown; the rest are counted
VERDICTS = ("PASS", "FAIL", "DEVIATION", "skipped")
ROLES = ("reproduction", "identity", "calibration", "validation")  # expected/README.md, "Roles and statuses"
STATUSES = ("settled", "inherent", "open")
OTHER_ROLES = ROLES[1:]  # not in the headline


class BadInput(Exception):
    """Exit 2: one line naming the parameter and what is allowed."""


# ---------------------------------------------------------------- what goes on the pages


@dataclass
class CitedTable:
    name: str
    description: str
    columns: list  # (name, unit)
    rows: list     # rows of formatted cells
    total_rows: int
    anchor: str = ""  # its id on the page


@dataclass
class ClaimRow:
    experiment: str
    id: str
    statement: str
    source: str
    expected: str
    band: str
    measured: str
    tolerance: str
    tolerance_kind: str
    tolerance_reason: str
    verdict: str
    known_deviation: str = ""
    deviation_band_kind: str = ""
    deviation_band_reason: str = ""
    role: str = ""         # "" for claims judged before issue 41 (shown as "—")
    status: str = ""       # of a known deviation; "" if none or not stated
    gist: str = ""         # the deviation box's first sentence (deviation_sentence)
    section: str = ""      # anchor of the section that shows it
    section_title: str = ""
    cited: list = field(default_factory=list)  # CitedTable shown in this claim's box (first on its page)
    cited_before: list = field(default_factory=list)  # (table name, anchor, claim id) shown in an earlier box
    commits_named: list = field(default_factory=list)  # commits its deviation text names other than the runs'

    @property
    def role_shown(self) -> str:
        return self.role or "—"

    @property
    def row_class(self) -> str:
        """Classes of its row in a claims table: verdict, role and status (the summary's filters)."""
        out = [self.verdict_class, "r-" + (self.role if self.role in ROLES else "none")]
        if self.verdict == "DEVIATION":
            out.append("s-" + (self.status if self.status in STATUSES else "none"))
        return " ".join(out)

    @property
    def anchor(self) -> str:
        return f"claim-{self.experiment}--{self.id}"

    @property
    def href(self) -> str:
        return f"{self.experiment}.html#{self.anchor}"

    @property
    def verdict_class(self) -> str:
        return "v-" + (self.verdict.lower() if self.verdict in VERDICTS else "other")


@dataclass
class Figure:
    id: str
    label: str          # "Luding (1998) Fig. 2"
    our_caption: str
    paper_caption: str
    caption_source: str
    image: str = ""     # href, "" if missing
    pdf: str = ""
    missing: str = ""   # why there is no image
    claims: list = field(default_factory=list)


@dataclass
class Experiment:
    name: str
    paper: str
    description: str
    has_results: bool
    scale: str = ""
    notes: list = field(default_factory=list)
    provenance: list = field(default_factory=list)  # (name, value)
    figures: list = field(default_factory=list)
    other_claims: list = field(default_factory=list)
    totals: dict = field(default_factory=dict)
    headline: dict | None = None  # the claims file's headline of this experiment, summed; None if it has none
    code_version: str = ""        # of the runs shown (summary.json), "0.1.0+5bd938e"
    commit: str = ""              # its commit, "5bd938e" ("" if it names none)

    @property
    def page(self) -> str:
        return f"{self.name}.html"

    @property
    def claims(self) -> list:
        return [c for f in self.figures for c in f.claims] + self.other_claims


def _totals(claims) -> dict:
    t = {v: 0 for v in VERDICTS}
    for c in claims:
        t[c.verdict] = t.get(c.verdict, 0) + 1
    t["total"] = len(claims)
    return t


def _num4(x: float) -> str:
    """A number as `granrepro check` prints it (4 significant digits)."""
    return "nan" if math.isnan(x) else f"{x:.4g}"


def _sig2(x: float) -> str:
    """A difference to 2 significant digits, without an exponent between 1e-4 and 1e6."""
    if x == 0 or not math.isfinite(x) or not 1e-4 <= abs(x) < 1e6:
        return f"{x:.2g}"
    digits = max(0, 1 - math.floor(math.log10(abs(x))))
    text = f"{round(x, digits):.{digits}f}"
    return text.rstrip("0").rstrip(".") if "." in text else text


def _paper_text(expected: str, tolerance: str) -> tuple[str, float | None, float, float]:
    """The paper's value or relation in words ("0.7 ± 0.05", "39 ± 5%", "range [1, inf]", "7, range
    [5.56, 8.81]") from the claims file's texts, with its value and the bounds it accepts."""
    m = re.fullmatch(r"\s*(?P<v>[^\s\[]+)?\s*(?:in \[(?P<lo>[^,\]]+), (?P<hi>[^\]]+)\])?\s*", expected or "")
    value = lo = hi = None
    try:
        if m and m.group("v"):
            value = float(m.group("v"))
        if m and m.group("lo"):
            lo, hi = float(m.group("lo")), float(m.group("hi"))
    except ValueError:
        m = None
    if not m or (value is None and lo is None):
        return (expected or "—"), None, -math.inf, math.inf
    kind, _, tol_text = (tolerance or "").partition(" ")
    try:
        tol = float(tol_text)
    except ValueError:
        tol = None
    text = f"{m.group('v')}" if value is not None else ""
    lo_t, hi_t = -math.inf, math.inf
    if value is not None and tol is not None and kind in ("abs", "rel"):
        width = tol if kind == "abs" else tol * abs(value)
        if tol > 0:
            text += f" ± {tol_text}" if kind == "abs" else f" ± {tol * 100:g}%"
        lo_t, hi_t = value - width, value + width
    if lo is not None:
        rng = (f"≥ {m.group('lo')}" if hi == math.inf and lo > -math.inf else
               f"≤ {m.group('hi')}" if lo == -math.inf and hi < math.inf else f"range [{m.group('lo')}, {m.group('hi')}]")
        text = f"{text}, {rng}" if text else rng
        lo_t, hi_t = max(lo_t, lo), min(hi_t, hi)
    return text, value, lo_t, hi_t


def deviation_sentence(c: dict) -> str:
    """The first sentence of a deviation box: what differs, by how much, the status. From the
    claim's fields in the claims file: "normal_branch_k200000: measured 0.8 against the paper's
    0.7 ± 0.05 (0.1 above, +14%; band [0.75, 0.85]); open." """
    cid, verdict = c.get("id", ""), c.get("verdict", "")
    paper, value, lo, hi = _paper_text(c.get("expected", ""), c.get("tolerance", ""))
    measured = c.get("measured")
    band = c.get("deviation_band") or ""
    status = c.get("status") or "status not stated"
    notes = []
    if not isinstance(measured, (int, float)) or isinstance(measured, bool):
        what = f"no measurement against the paper's {paper}"
    else:
        x = float(measured)
        what = f"measured {_num4(x)} {'within' if lo <= x <= hi else 'against'} the paper's {paper}"
        if x < lo or x > hi:
            ref = value if value is not None else (lo if x < lo else hi)
            d = abs(x - ref)
            off = f"{_sig2(d)} {'below' if x < ref else 'above'}"
            if value is not None and value != 0:
                off += f", {(x - value) / abs(value):+.0%}"
            notes.append(off)
    if band:
        notes.append(("band " if verdict == "DEVIATION" else "deviation band ") + band)
    if verdict == "skipped":
        notes.insert(0, "not judged at this scale")
    elif verdict == "FAIL":
        notes.append("FAIL: outside the band too" if band else "FAIL")
    elif verdict == "PASS":
        notes.insert(0, "PASS")
    return f"{cid}: {what}" + (f" ({'; '.join(notes)})" if notes else "") + f"; {status}."


def _number(v) -> str:
    if v is None:
        return "—"
    if isinstance(v, bool):
        return str(v).lower()
    if isinstance(v, (int, float)):
        return "nan" if isinstance(v, float) and math.isnan(v) else f"{v:.6g}"
    try:
        return f"{float(v):.6g}"
    except (TypeError, ValueError):
        return str(v)


# ---------------------------------------------------------------- claims -> figure sections

_FIG = re.compile(r"\bFig(?:ure|s?\.)\s*(\d+(?:\s*\([a-z]\))?(?:\s*(?:,|and|-)\s*\(?[0-9a-z]+\)?)*)")


def figures_named(source: str) -> list[int]:
    """The figure numbers a claim's source names, in order ("Figs. 13 and 14" -> [13, 14])."""
    out = []
    for m in _FIG.finditer(source):
        out += [int(n) for n in re.findall(r"\d+", m.group(1))]
    return out


def figure_number(fig_id: str) -> int:
    m = re.search(r"fig0*(\d+)$", fig_id)
    return int(m.group(1)) if m else -1


def figure_of_claim(claim: dict, fig_ids: list[str]) -> str:
    """The id of the figure section that shows the claim, "" for the experiment's other claims: the
    figure it names (`figure`, checked by granrepro against the experiment's ids), else the first
    one its source cites."""
    if claim.get("figure") in fig_ids:
        return claim["figure"]
    by_number = {figure_number(f): f for f in fig_ids}
    for n in figures_named(claim.get("source", "")):
        if n in by_number:
            return by_number[n]
    return ""


# ---------------------------------------------------------------- tables the deviation texts cite


def tables_cited(text: str, names) -> list[str]:
    """Names of `names` the text cites: tables/NAME.tsv, NAME.tsv, "table NAME", or a NAME with an
    underscore or a digit standing as a word (a plain word such as `seeds` only in the first forms)."""
    found = []
    for n in sorted(names, key=len, reverse=True):
        e = re.escape(n)
        explicit = re.search(rf"(tables/{e}\.tsv|(?<![\w.]){e}\.tsv|\btables? {e}(?![\w.]))", text)
        word = re.search(rf"(?<![\w./-]){e}(?![\w])", text) and re.search(r"[_0-9]", n)
        if explicit or word:
            found.append(n)
    return [n for n in sorted(names) if n in found]


def cited_table(t) -> CitedTable:
    cols = list(t)
    n = max((len(t[c]) for c in cols), default=0)
    rows = []
    for i in range(min(n, MAX_TABLE_ROWS)):
        rows.append([_number(t[c][i].item() if hasattr(t[c][i], "item") else t[c][i]) if i < len(t[c]) else ""
                     for c in cols])
    return CitedTable(t.name, t.description, [(c, t.units.get(c, "")) for c in cols], rows, n)


def place_cited_tables(e: Experiment, run) -> None:
    """Each table the deviation texts of a page cite, shown once: in the box of the first claim (in
    page order) that cites it; the later boxes refer to it."""
    shown = {}
    rows = [c for f in e.figures for c in f.claims] + e.other_claims
    for c in rows:
        if not c.known_deviation:
            continue
        for n in tables_cited(" ".join((c.known_deviation, c.deviation_band_reason, c.tolerance_reason)),
                              run.tables.keys()):
            if n in shown:
                c.cited_before.append((n, *shown[n]))
            else:
                t = cited_table(run.tables[n])
                t.anchor = f"table-{len(shown) + 1}"
                shown[n] = (t.anchor, c.id)
                c.cited.append(t)


_COMMIT = re.compile(r"(?<![0-9A-Za-z_])(?=[0-9a-f]*[a-f])(?=[0-9a-f]*[0-9])[0-9a-f]{7,40}(?![0-9A-Za-z_])")


def commits_in(text: str) -> list[str]:
    """The git commits a text names (7 to 40 hex digits with a letter and a digit), each once, in order."""
    return list(dict.fromkeys(_COMMIT.findall(text or "")))


def _same_commit(a: str, b: str) -> bool:
    return bool(b) and (a.startswith(b) or b.startswith(a))


# ---------------------------------------------------------------- the headline (issue 41)


def _zero_headline() -> dict:
    return {"statements": 0, "reproduced": 0, "deviate": 0, "fail": 0, "status": {s: 0 for s in STATUSES},
            "other": {r: 0 for r in OTHER_ROLES}, "other_verdicts": {v: 0 for v in ("PASS", "FAIL", "DEVIATION")}}


def _add(into: dict, h: dict) -> None:
    for k in ("statements", "reproduced", "deviate", "fail"):
        into[k] += h.get(k, 0)
    for k in ("status", "other", "other_verdicts"):
        for name, n in (h.get(k) or {}).items():
            into[k][name] = into[k].get(name, 0) + n


def _sum(headlines) -> dict | None:
    """The sum of headline counts (None where none is given; None if none is)."""
    given = [h for h in headlines if h is not None]
    if not given:
        return None
    out = _zero_headline()
    for h in given:
        _add(out, h)
    return out


def sum_headlines(entries) -> dict | None:
    """An experiment's headline entries (one per paper its claims name) summed."""
    return _sum(entries) if isinstance(entries, list) and entries else None


def headline_lines(experiments: list, totals: dict) -> dict:
    """The headline as `granrepro check --all` prints it for the same folder: per paper (the claims
    file's headline entries grouped by paper and summed, papers in the order first seen), its line
    and its line of the claims not in the headline, and the totals line of every claim."""
    papers = {}
    for x in experiments:
        if not x.get("has_results"):
            continue
        for h in x.get("headline") or []:
            _add(papers.setdefault(h["paper"], _zero_headline()), h)
    lines, others = [], []
    for paper, c in papers.items():
        st, ot, ov = c["status"], c["other"], c["other_verdicts"]
        lines.append(f"{paper}: {c['statements']} statements \u2014 {c['reproduced']} reproduced, {c['deviate']} deviate "
                     f"({st.get('settled', 0)} settled, {st.get('inherent', 0)} inherent, {st.get('open', 0)} open)"
                     + (f", {c['fail']} FAIL" if c["fail"] else ""))
        others.append(f"{paper}, not in the headline: {ot.get('identity', 0)} identity, "
                      f"{ot.get('calibration', 0)} calibration, {ot.get('validation', 0)} validation "
                      f"({ov.get('PASS', 0)} PASS, {ov.get('FAIL', 0)} FAIL, {ov.get('DEVIATION', 0)} DEVIATION)")
    return {"papers": lines, "others": others,
            "totals": f"totals: {totals['PASS']} PASS, {totals['FAIL']} FAIL, {totals['DEVIATION']} DEVIATION, "
                      f"{totals['skipped']} skipped"}


# ---------------------------------------------------------------- images


MAGIC = {".png": PNG_MAGIC, ".pdf": PDF_MAGIC}


def find_file(results: str, experiment: str, fig_id: str, ext: str) -> str:
    """The first of OUT/<experiment>/<id><ext> and OUT/<id><ext> that exists (as a name: a symlink
    counts, and is then refused by figure_file rather than passed over)."""
    for p in (os.path.join(results, experiment, fig_id + ext), os.path.join(results, fig_id + ext)):
        if os.path.lexists(p):
            return p
    return ""


def figure_file(path: str, ext: str, head: int | None = None) -> bytes:
    """The content of a figure (its first `head` bytes): a regular file (not a symlink, at most
    MAX_IMAGE_BYTES) that is PNG or PDF by its first bytes. ResultsError (naming the file) otherwise."""
    data = read_file(path, MAX_IMAGE_BYTES, "figure", head=head)
    if not data.startswith(MAGIC[ext]):
        raise ResultsError(f"{path}: not a {ext[1:].upper()} file by its first bytes")
    return data


# ---------------------------------------------------------------- the model of the whole report


def _data():
    return resources.files("granrepro.report")


def load_figure_texts() -> dict:
    return tomllib.loads(_data().joinpath("figures.toml").read_text(encoding="utf-8"))


def provenance_rows(summary: dict, run) -> list:
    rows = [("code version", summary.get("code_version", "")),
            ("command line", summary.get("command_line", "")),
            ("--set overrides", ", ".join(f"{k}={v}" for k, v in (summary.get("overridden_parameters") or {}).items())
             or "none"),
            ("seed", summary.get("seed", "")),
            ("scale", summary.get("scale", "")),
            ("wall time", f"{summary['wall_time_s']:.1f} s" if isinstance(summary.get("wall_time_s"), (int, float)) else "")]
    if "resumed_points" in summary:
        rows.append(("resumed sweep points", summary["resumed_points"]))
    if run is not None:
        a = run.attributes
        for k in ("created_utc", "threads", "paper"):
            if k in a:
                rows.append((k, a[k]))
        for k, v in run.provenance.items():
            if k in ("command_line", "overridden_parameters"):
                continue
            if isinstance(v, str) and (len(v) > 200 or "\n" in v):
                continue  # the expected/, experiments/ and plots/ texts used: in data.h5
            rows.append((k, v))
        long = sorted(k for k, v in run.provenance.items() if isinstance(v, str) and (len(v) > 200 or "\n" in v))
        if long:
            rows.append(("also in data.h5 /provenance", ", ".join(long)))
    return [(k, _number(v) if isinstance(v, float) else str(v)) for k, v in rows]


def shown_name(results: str) -> str:
    """The results folder as the pages name it: as the user gave it (`--out paper_figures`), the
    folder's own name where that is only "." or ".."."""
    n = os.path.normpath(results)
    return os.path.basename(os.path.abspath(results)) if n in (".", "..") or n.endswith("/..") else n


def figure_image(results: str, name: str, fid: str, ext: str, warn) -> str:
    """The figure's file if it can be shown, "" if there is none or it is refused (warned)."""
    path = find_file(results, name, fid, ext)
    if path:
        try:
            figure_file(path, ext, head=len(MAGIC[ext]))
        except ResultsError as e:
            warn(f"figure {fid} ({name}): {e}; not shown")
            return ""
    return path


def build_model(results: str, judged: dict, final_to: str, link_images: bool, warn) -> dict:
    from .. import reader

    texts = load_figure_texts()
    papers = {}  # paper_key -> the paper's row, in the order of its first experiment (the registry's)
    for x in judged["experiments"]:
        if x.get("paper_key") and x["paper_key"] not in papers:
            papers[x["paper_key"]] = {"key": x["paper_key"], "title": x.get("paper_citation") or x.get("paper", ""),
                                      "experiments": []}
    shown = shown_name(results)
    copies = []  # (source file, extension, name in the report)
    experiments = []
    for x in judged["experiments"]:
        name = x["name"]
        e = Experiment(name, x.get("paper", ""), x.get("description", ""), bool(x.get("has_results")))
        fig_ids = [f["id"] for f in x.get("figures", [])]
        run = None
        claims_in = x.get("claims", []) if e.has_results else []
        if e.has_results:
            e.scale = x.get("scale", "")
            e.notes = list(x.get("notes", []))
            texts_of = lambda c: " ".join(c.get(k, "") for k in ("known_deviation", "deviation_band_reason",  # noqa: E731
                                                                   "tolerance_reason"))
            # data.h5 and summary.json read and verified against each other; of the tables only
            # those a deviation text cites.
            run = reader.load(os.path.join(results, name), points=False,
                              tables=lambda names: {n for c in claims_in for n in tables_cited(texts_of(c), names)})
            e.provenance = provenance_rows(run.summary, run)
        for f in x.get("figures", []):
            fid = f["id"]
            t = texts.get("figure", {}).get(fid, {})
            who = x.get("paper_short") or fid.split("-")[0]
            fig = Figure(fid, f"{who} Fig. {figure_number(fid)}", f.get("caption", ""), t.get("caption", ""),
                         t.get("source", ""))
            if not e.has_results:
                fig.missing = f"no results of {name} in {shown}"
            else:
                png = figure_image(results, name, fid, ".png", warn)
                pdf = figure_image(results, name, fid, ".pdf", warn) if png else ""
                if not png:
                    fig.missing = f"{fid}.png is missing from {shown} or is not a PNG file (the figure was not drawn)"
                    warn(f"figure {fid} ({name}): {fid}.png is missing from {results} or is not a PNG file")
                for path, ext, attr in ((png, ".png", "image"), (pdf, ".pdf", "pdf")):
                    if not path:
                        continue
                    if link_images:
                        setattr(fig, attr, os.path.relpath(os.path.abspath(path), final_to))
                    else:
                        target = f"figures/{os.path.basename(path)}"
                        copies.append((path, ext, target))
                        setattr(fig, attr, target)
            e.figures.append(fig)
        by_id = {f.id: f for f in e.figures}
        for c in claims_in:
            row = ClaimRow(name, c["id"], c.get("statement", ""), c.get("source", ""), c.get("expected", ""),
                           c.get("deviation_band", ""), _number(c.get("measured")), c.get("tolerance", ""),
                           c.get("tolerance_kind", ""), c.get("tolerance_reason", ""), c.get("verdict", "FAIL"),
                           c.get("known_deviation", ""), c.get("deviation_band_kind", ""),
                           c.get("deviation_band_reason", ""))
            row.role, row.status = c.get("role") or "", (c.get("status") or "") if row.known_deviation else ""
            if row.known_deviation:
                row.gist = deviation_sentence(c)
            fid = figure_of_claim(c, fig_ids)
            if fid:
                by_id[fid].claims.append(row)
                row.section, row.section_title = fid, by_id[fid].label
            else:
                e.other_claims.append(row)
                row.section, row.section_title = f"{name}-other", f"other claims of {name}"
        if run is not None:
            e.code_version = str(run.summary.get("code_version", "") or "")
            e.commit = next(iter(commits_in(e.code_version)), "")
            place_cited_tables(e, run)
            for c in e.claims:
                c.commits_named = [h for h in commits_in(" ".join((c.known_deviation, c.deviation_band_reason,
                                                                     c.tolerance_reason)))
                                   if not _same_commit(h, e.commit)]
        e.totals = _totals(e.claims)
        e.headline = sum_headlines(x.get("headline")) if e.has_results else None
        experiments.append(e)
        if x.get("paper_key"):
            papers[x["paper_key"]]["experiments"].append(e)
    # in the order of the experiments (the registry's), as `check --all` prints its papers
    papers = list(papers.values())
    for p, x in ((p, x) for p in papers for x in judged["experiments"] if x["name"] in {e.name for e in p["experiments"]}):
        if "name" not in p and x.get("has_results") and x.get("headline"):
            p["name"] = x["headline"][0]["paper"]  # "Luding 1998", as the headline names it
    for p in papers:
        p["totals"] = _totals([c for e in p["experiments"] for c in e.claims])
        p["headline"] = _sum([e.headline for e in p["experiments"]])
        p.setdefault("name", "")
    ordered = [e for p in papers for e in p["experiments"]]
    ordered += [e for e in experiments if e not in ordered]
    claims = [c for e in ordered for c in e.claims]
    totals = _totals(claims)
    return {"papers": [p for p in papers if p["experiments"]], "experiments": experiments, "claims": claims,
            "totals": totals, "results": shown, "verdicts": VERDICTS, "roles": ROLES, "statuses": STATUSES,
            "headline": headline_lines(judged["experiments"], totals),
            "all_headline": _sum([e.headline for e in experiments]),
            "missing_results": [e.name for e in experiments if not e.has_results],
            "missing_figures": [(e, f) for e in experiments for f in e.figures if f.missing and e.has_results],
            "scales": sorted({e.scale for e in experiments if e.scale}),
            "versions": sorted({dict(e.provenance).get("code version", "") for e in experiments if e.has_results}),
            "copies": copies}


# ---------------------------------------------------------------- writing


def breakable(text: str):
    """The text escaped, with a line break allowed after each '_' (a long claim id in a narrow column)."""
    import markupsafe

    return markupsafe.escape(text).replace("_", markupsafe.Markup("_<wbr>"))


def render(model: dict, staging: str) -> None:
    import jinja2

    env = jinja2.Environment(loader=jinja2.PackageLoader("granrepro.report", "templates"),
                             autoescape=True, undefined=jinja2.StrictUndefined,
                             trim_blocks=True, lstrip_blocks=True)
    env.filters["breakable"] = breakable
    pages = {"index.html": env.get_template("index.html.j2").render(**model)}
    for e in model["experiments"]:
        if e.has_results:  # an experiment without results is listed on the summary, without a page
            pages[e.page] = env.get_template("experiment.html.j2").render(e=e, **model)
    pages["style.css"] = _data().joinpath("templates", "style.css").read_text(encoding="utf-8")
    pages[MARKER] = "written by `granrepro report`; the whole folder is replaced by the next report\n"
    for name, text in pages.items():
        _write(os.path.join(staging, name), text.encode("utf-8"))
    for src, ext, target in model["copies"]:
        dst = os.path.join(staging, target)
        os.makedirs(os.path.dirname(dst), exist_ok=True)
        _write(dst, figure_file(src, ext))  # checked again as it is read: only a PNG/PDF is copied


def _write(path: str, data: bytes) -> None:
    with open(path, "wb") as f:
        f.write(data)
        f.flush()
        os.fsync(f.fileno())


def _fsync_dir(path: str) -> None:
    fd = os.open(path, os.O_RDONLY | os.O_DIRECTORY)
    try:
        os.fsync(fd)
    finally:
        os.close(fd)


def _alive(pid: int) -> bool:
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except PermissionError:
        return True
    return True


def _clean_leftovers(parent: str, base: str, final: str) -> None:
    """What killed reports left: .<base>.partial-<pid> (deleted) and .<base>.old-<pid> (put back if
    the report is missing, else deleted), of processes no longer running."""
    for n in os.listdir(parent):
        m = re.fullmatch(rf"\.{re.escape(base)}\.(partial|old)-(\d+)", n)
        if not m or _alive(int(m.group(2))):
            continue
        path = os.path.join(parent, n)
        if m.group(1) == "old" and not os.path.exists(final):
            os.rename(path, final)
        else:
            shutil.rmtree(path, ignore_errors=True)


def _exchange(a: str, b: str) -> bool:
    """renameat2(RENAME_EXCHANGE): swaps two folders in one step; False where unsupported."""
    try:
        libc = ctypes.CDLL(None, use_errno=True)
        f = libc.renameat2
    except (OSError, AttributeError):
        return False
    at_fdcwd, rename_exchange = -100, 2
    return f(at_fdcwd, os.fsencode(a), at_fdcwd, os.fsencode(b), rename_exchange) == 0


def commit(staging: str, final: str, old: str) -> None:
    """Puts the staged report in place of the old one: nothing half-written is ever at `final`."""
    _fsync_dir(staging)
    if not os.path.exists(final):
        os.rename(staging, final)
    elif _exchange(staging, final):
        shutil.rmtree(staging)  # now the old report
    else:
        os.rename(final, old)
        os.rename(staging, final)
        shutil.rmtree(old)
    _fsync_dir(os.path.dirname(final))


def check_target(results: str, to: str) -> None:
    r = os.path.realpath(results)
    f = os.path.realpath(to)
    final = to
    if f == r or r.startswith(f.rstrip("/") + "/"):
        raise BadInput(f"--to {final}: is the results folder or holds it; give a folder of its own (default: OUT/report)")
    if os.path.exists(final):
        if not os.path.isdir(final):
            raise BadInput(f"--to {final}: exists and is not a folder; give a new folder or an earlier report's")
        if os.listdir(final) and not os.path.exists(os.path.join(final, MARKER)):
            raise BadInput(f"--to {final}: exists and is not a report of `granrepro report` (no {MARKER} in it), "
                           "so it is not replaced; give a new folder or an earlier report's")


def make_report(results: str, judged: dict, to: str, warn=None) -> dict:
    """Writes the report of `results` to `to`; returns the model (tests read it)."""
    warn = warn or (lambda m: print(f"granrepro: report: warning: {printable(m)}", file=sys.stderr))
    if not os.path.isdir(results):
        raise BadInput(f"--results {results}: not a folder; give a results folder such as paper_figures or out")
    final = os.path.abspath(to)
    check_target(results, to)
    parent, base = os.path.dirname(final), os.path.basename(final)
    try:
        os.makedirs(parent, exist_ok=True)
    except OSError as e:
        raise BadInput(f"--to {to}: its folder cannot be created ({e.strerror})") from e
    if not os.access(parent, os.W_OK):
        raise BadInput(f"--to {to}: {parent} is not writable")
    r = os.path.realpath(results).rstrip("/") + "/"
    link_images = os.path.realpath(final).startswith(r)  # inside the results: link, else copy
    model = build_model(results, judged, final, link_images, warn)
    _clean_leftovers(parent, base, final)
    staging = os.path.join(parent, f".{base}.partial-{os.getpid()}")
    shutil.rmtree(staging, ignore_errors=True)
    os.mkdir(staging)
    try:
        render(model, staging)
        commit(staging, final, os.path.join(parent, f".{base}.old-{os.getpid()}"))
    except BaseException:
        shutil.rmtree(staging, ignore_errors=True)
        raise
    return model


# ---------------------------------------------------------------- the claims file


_NAME = re.compile(r"[a-z0-9][a-z0-9-]{0,63}")  # an experiment or figure id: also a file name here
_CLAIM_TEXTS = ("statement", "source", "expected", "tolerance", "tolerance_reason", "tolerance_kind", "verdict",
                "known_deviation", "deviation_band", "deviation_band_kind", "deviation_band_reason")
_COUNTS = ("statements", "reproduced", "deviate", "fail")
_COUNT_NAMES = {"status": STATUSES, "other": OTHER_ROLES, "other_verdicts": ("PASS", "FAIL", "DEVIATION")}
_MAX_COUNT = 10**6


def _count(where: str, v) -> None:
    if not isinstance(v, int) or isinstance(v, bool) or not 0 <= v <= _MAX_COUNT:
        raise BadInput(f"{where} must be a count (an integer from 0 to {_MAX_COUNT})")


def _validate_headline(at: str, headline) -> None:
    """An experiment's headline as `granrepro report` writes it (headline_json): absent in claims
    files of before issue 41."""
    _field(at, headline, list, "an array")
    for k, h in enumerate(headline or []):
        where = f"{at}[{k}]"
        _field(where, h, dict, "an object", optional=False)
        _field(f"{where}.paper", h.get("paper"), str, "text", optional=False)
        for key in _COUNTS:
            _count(f"{where}.{key}", h.get(key))
        for key, names in _COUNT_NAMES.items():
            _field(f"{where}.{key}", h.get(key), dict, "an object", optional=False)
            for name, n in h[key].items():
                if name not in names:
                    raise BadInput(f"{where}.{key} names '{printable(name)[:40]}'; allowed: {', '.join(names)}")
                _count(f"{where}.{key}.{name}", n)


def _field(where: str, value, kind, what: str, optional: bool = True):
    if value is None and optional:
        return
    if not isinstance(value, kind) or (kind is int and isinstance(value, bool)):
        raise BadInput(f"{where} must be {what}")


def validate_judged(judged, file: str) -> None:
    """The claims file as `granrepro report` writes it (module doc), or BadInput naming the field:
    its names become file names and its texts go on the pages."""
    if not isinstance(judged, dict) or not isinstance(judged.get("experiments"), list):
        raise BadInput(f"--claims {file}: not the claims `granrepro report` writes (no 'experiments' list)")
    seen = set()
    for i, x in enumerate(judged["experiments"]):
        at = f"--claims {file}: experiments[{i}]"
        _field(at, x, dict, "an object", optional=False)
        name = x.get("name")
        if not isinstance(name, str) or not _NAME.fullmatch(name) or name in seen:
            raise BadInput(f"{at}.name must be an experiment name (a-z, 0-9, '-'), each once")
        seen.add(name)
        for k in ("paper", "paper_short", "paper_citation", "description", "scale"):
            _field(f"{at}.{k}", x.get(k), str, "text")
        if x.get("paper_key") is not None and not (isinstance(x["paper_key"], str) and _NAME.fullmatch(x["paper_key"])):
            raise BadInput(f"{at}.paper_key must be a paper key (a-z, 0-9, '-')")
        _field(f"{at}.has_results", x.get("has_results"), bool, "true or false")
        for key in ("figures", "notes", "claims", "smoke"):
            _field(f"{at}.{key}", x.get(key), list, "an array")
        for j, f in enumerate(x.get("figures") or []):
            _field(f"{at}.figures[{j}]", f, dict, "an object", optional=False)
            if not isinstance(f.get("id"), str) or not _NAME.fullmatch(f["id"]):
                raise BadInput(f"{at}.figures[{j}].id must be a figure id (a-z, 0-9, '-')")
            _field(f"{at}.figures[{j}].caption", f.get("caption"), str, "text")
        for j, n in enumerate(x.get("notes") or []):
            _field(f"{at}.notes[{j}]", n, str, "text", optional=False)
        _validate_headline(f"{at}.headline", x.get("headline"))
        for j, c in enumerate(x.get("claims") or []):
            _field(f"{at}.claims[{j}]", c, dict, "an object", optional=False)
            _field(f"{at}.claims[{j}].id", c.get("id"), str, "text", optional=False)
            for k in _CLAIM_TEXTS:
                _field(f"{at}.claims[{j}].{k}", c.get(k), str, "text")
            # absent in claims judged before issue 41 (shown as "—"); else one of expected/README.md's
            for k, allowed in (("role", ROLES), ("status", STATUSES)):
                if c.get(k) is not None and c[k] not in allowed:
                    raise BadInput(f"{at}.claims[{j}].{k} must be one of {', '.join(allowed)}")
            _field(f"{at}.claims[{j}].measured", c.get("measured"), (int, float), "a number or null")


def read_claims(path: str) -> dict:
    try:
        judged = read_json(path, MAX_SUMMARY_BYTES, "claims file")
    except ResultsError as e:
        raise BadInput(f"--claims {e}") from None
    validate_judged(judged, path)
    return judged


# ---------------------------------------------------------------- the command


class _Parser(argparse.ArgumentParser):
    def error(self, message):  # one line, exit 2
        print(f"granrepro: report: {printable(message)}", file=sys.stderr)
        sys.exit(2)


def _say(message: str) -> None:
    print(f"granrepro: report: {printable(message)}", file=sys.stderr)


def main(argv=None) -> int:
    p = _Parser(prog="python3 -m granrepro.report", description=__doc__.split("\n\n")[0])
    p.add_argument("--results", required=True, help="results folder (OUT of the runs, or paper_figures)")
    p.add_argument("--claims", required=True, help="the judged claims, as `granrepro report` writes them")
    p.add_argument("--to", required=True, help="report folder (replaced when the new report is complete)")
    a = p.parse_args(argv)
    for module, package in (("jinja2", "python3-jinja2"), ("h5py", "python3-h5py"), ("numpy", "python3-numpy")):
        try:
            __import__(module)
        except ImportError:
            print(f"granrepro: report needs the Python module {module} (Debian: apt-get install {package}; "
                  f"or pip install ./python)", file=sys.stderr)
            return 4
    try:
        model = make_report(a.results, read_claims(a.claims), a.to,
                            warn=lambda m: _say(f"warning: {m}"))
    except (BadInput, ResultsError) as e:  # damaged or edited results, a wrong argument
        _say(str(e))
        return 2
    except OSError as e:  # only writing is left to fail so: every read is a ResultsError
        _say(f"could not write {a.to}: {e.strerror or e} ({e.filename or ''}); the previous report is untouched")
        return 3
    except KeyboardInterrupt:
        _say("interrupted; the previous report is untouched")
        return 130
    except Exception as e:  # a last resort: one line, never a traceback
        _say(f"internal error ({type(e).__name__}: {str(e).splitlines()[0][:200] if str(e) else ''}); "
             "the previous report is untouched; please report it with the command")
        return 1
    t = model["totals"]
    print(f"report: {os.path.join(a.to, 'index.html')}: {len(model['experiments']) - len(model['missing_results'])} "
          f"experiments, {t['total']} claims ({t['PASS']} PASS, {t['FAIL']} FAIL, {t['DEVIATION']} DEVIATION, "
          f"{t['skipped']} skipped), {len(model['missing_figures'])} figures missing")
    return 0
