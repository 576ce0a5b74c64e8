# granrepro report (python/granrepro/report) on quick-scale runs of brake-failure and
# emergency-brake: every claim appears exactly once, every text is escaped, a missing figure is
# reported, bad input exits 2 with one line, and a report replaces the previous one whole.
import html
import json
import os
import re
import shutil
import subprocess

import pytest

from granrepro.report import BadInput, make_report
from granrepro.report.build import validate_judged


def report(binary, out, to, *more):
    return subprocess.run([binary, "report", "--out", str(out), "--to", str(to), *more], capture_output=True, text=True)


def page(path):
    with open(path, encoding="utf-8") as f:
        return f.read()


def test_every_claim_appears_once_in_a_section_and_once_in_the_summary(binary, quick_out, tmp_path):
    r = report(binary, quick_out, tmp_path / "report")
    assert r.returncode == 0, r.stderr
    index = page(tmp_path / "report" / "index.html")
    for exp in ("brake-failure", "emergency-brake"):
        with open(os.path.join(quick_out, exp, "summary.json")) as f:
            claims = json.load(f)["claims"]
        assert claims
        text = page(tmp_path / "report" / f"{exp}.html")
        for c in claims:
            anchor = f"claim-{exp}--{c['id']}"
            assert text.count(f'id="{anchor}"') == 1, anchor
            assert index.count(f'href="{exp}.html#{anchor}"') == 1, anchor
        # every figure of the experiment has its section, with our PNG (copied: --to is elsewhere)
        for fig in re.findall(r'<section id="([^"]+)"', text):
            if not fig.endswith("-other"):
                assert f'<img src="figures/{fig}.png"' in text, fig
    # the other experiments have no results here: listed, not failed
    assert "No results in" in index and "cooling" in index
    assert "report:" in r.stdout and "0 figures missing" in r.stdout


def judged_of(out, exp, **changes):
    with open(os.path.join(out, exp, "summary.json")) as f:
        s = json.load(f)
    claims = s["claims"]
    for k, v in changes.items():
        claims[0][k] = v
    return {"experiments": [{"name": exp, "paper": "", "description": "", "has_results": True, "scale": s["scale"],
                             "notes": [], "claims": claims,
                             "figures": [{"id": "schaefer95-fig3", "caption": "<b>ours</b>"}]}]}


def copy_run(quick_out, tmp_path, exp="brake-failure", png=True):
    results = tmp_path / "results"
    shutil.copytree(os.path.join(quick_out, exp), results / exp,
                    ignore=None if png else shutil.ignore_patterns("*.png", "*.pdf"))
    return results


def test_every_text_is_escaped(quick_out, tmp_path):
    results = copy_run(quick_out, tmp_path)
    evil = "<script>alert('x')</script> & <img src=x onerror=alert(1)>"
    judged = judged_of(results, "brake-failure", statement=evil, known_deviation=evil, source=evil,
                       deviation_band="[1, 2]")
    make_report(str(results), judged, str(tmp_path / "report"), warn=lambda m: None)
    for name in ("index.html", "brake-failure.html"):
        text = page(tmp_path / "report" / name)
        assert "<script>alert" not in text and "<img src=x" not in text and "<b>ours</b>" not in text
        assert "&lt;script&gt;alert(&#39;x&#39;)&lt;/script&gt; &amp; &lt;img src=x onerror=alert(1)&gt;" in text
    assert "&lt;b&gt;ours&lt;/b&gt;" in page(tmp_path / "report" / "brake-failure.html")


def test_a_missing_figure_is_reported_on_the_page_and_on_stderr(quick_out, tmp_path):
    results = copy_run(quick_out, tmp_path, png=False)
    warnings = []
    model = make_report(str(results), judged_of(results, "brake-failure"), str(tmp_path / "report"),
                        warn=warnings.append)
    assert [f.id for _, f in model["missing_figures"]] == ["schaefer95-fig3"]
    assert warnings and "schaefer95-fig3.png is missing" in warnings[0]
    text = page(tmp_path / "report" / "brake-failure.html")
    assert "missing-figure" in text and "<img" not in text
    assert 'href="brake-failure.html#schaefer95-fig3"' in page(tmp_path / "report" / "index.html")


def test_bad_input_is_one_line_naming_the_parameter(binary, quick_out, tmp_path):
    r = report(binary, tmp_path / "nowhere", tmp_path / "report")
    assert r.returncode == 2 and r.stderr.count("\n") == 1 and "--out" in r.stderr, r.stderr
    empty = tmp_path / "empty"
    empty.mkdir()
    r = report(binary, empty, tmp_path / "report")
    assert r.returncode == 2 and "no results" in r.stderr and r.stderr.count("\n") == 1, r.stderr
    # a folder that is not a report is never replaced, nor the results folder
    other = tmp_path / "mine"
    other.mkdir()
    (other / "notes.txt").write_text("keep me")
    r = report(binary, quick_out, other)
    assert r.returncode == 2 and "--to" in r.stderr and r.stderr.count("\n") == 1, r.stderr
    assert (other / "notes.txt").read_text() == "keep me"
    r = report(binary, quick_out, quick_out)
    assert r.returncode == 2 and "--to" in r.stderr, r.stderr
    with pytest.raises(BadInput, match="--results"):
        make_report(str(tmp_path / "nowhere"), {"experiments": []}, str(tmp_path / "r"))


def test_a_report_replaces_the_previous_one_whole(binary, quick_out, tmp_path):
    to = tmp_path / "report"
    assert report(binary, quick_out, to).returncode == 0
    (to / "stale.html").write_text("from before")
    r = report(binary, quick_out, to)
    assert r.returncode == 0, r.stderr
    assert not (to / "stale.html").exists() and (to / "index.html").exists()
    assert [n for n in os.listdir(tmp_path) if n.startswith(".report.")] == []
    # outside the results folder the figures are copied, so the folder stands alone
    assert (to / "figures" / "schaefer95-fig3.png").exists()


def test_the_default_report_links_the_figures_of_its_results_folder(binary, quick_out):
    r = subprocess.run([binary, "report", "--out", str(quick_out)], capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    text = page(os.path.join(quick_out, "report", "brake-failure.html"))
    assert '<img src="../brake-failure/schaefer95-fig3.png"' in text
    assert not os.path.exists(os.path.join(quick_out, "report", "figures"))
    shutil.rmtree(os.path.join(quick_out, "report"))


def test_pages_only_for_the_experiments_present_each_naming_the_folder(binary, quick_out, tmp_path):
    # --out as the user gave it (relative): every page names it, as the committed report names
    # paper_figures (issue 40 §6: it said paper_figures.new, a folder that does not exist).
    shutil.copytree(os.path.join(quick_out, "brake-failure"), tmp_path / "one" / "brake-failure",
                    ignore=shutil.ignore_patterns("report"))
    r = subprocess.run([binary, "report", "--out", "one", "--to", "rep"], capture_output=True, text=True, cwd=tmp_path)
    assert r.returncode == 0, r.stderr
    pages = sorted(n for n in os.listdir(tmp_path / "rep") if n.endswith(".html"))
    assert pages == ["brake-failure.html", "index.html"]
    for n in pages:
        assert "from <code>one</code>" in page(tmp_path / "rep" / n), n
    index = page(tmp_path / "rep" / "index.html")
    assert "Results in <code>one</code>" in index and "No results in <code>one</code> for: " in index
    assert 'href="cooling.html' not in index and "cooling" in index


def test_the_papers_come_from_the_experiment_files(binary, quick_out, tmp_path):
    # `granrepro list --json` prints each experiment's paper as experiments/<name>.toml names it;
    # the report shows that citation for the paper and labels the figures with its short name.
    r = subprocess.run([binary, "list", "--json"], capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    listing = {x["name"]: x for x in json.loads(r.stdout)["experiments"]}
    assert "brake-failure" in listing
    bf = listing["brake-failure"]
    assert all(f["id"].startswith(bf["paper_key"] + "-") for f in bf["figures"])
    assert all("=" in s for x in listing.values() for s in x["smoke"]) and all(x["smoke"] for x in listing.values())
    r = report(binary, quick_out, tmp_path / "report")
    assert r.returncode == 0, r.stderr
    assert html.escape(bf["paper_citation"], quote=False) in page(tmp_path / "report" / "index.html")
    assert html.escape(f"{bf['paper_short']} Fig. 3", quote=False) in page(tmp_path / "report" / "brake-failure.html")
    # the same from a claims file naming another paper: nothing about the papers is kept in Python
    results = copy_run(quick_out, tmp_path)
    judged = judged_of(results, "brake-failure")
    judged["experiments"][0].update(paper_key="schaefer95", paper_short="Zed (2099)", paper_citation="Z. Zed, A title (2099)")
    make_report(str(results), judged, str(tmp_path / "other"), warn=lambda m: None)
    assert "Z. Zed, A title (2099)" in page(tmp_path / "other" / "index.html")
    assert "Zed (2099) Fig. 3" in page(tmp_path / "other" / "brake-failure.html")
    judged["experiments"][0]["paper_key"] = "../x"
    with pytest.raises(BadInput, match=r"experiments\[0\]\.paper_key must be a paper key"):
        validate_judged(judged, "claims.json")


PAPER_FIGURES = os.path.join(os.path.dirname(__file__), "..", "..", "paper_figures")


def test_the_committed_report_is_what_the_code_writes(binary, tmp_path):
    """`granrepro report --out paper_figures` (the README's default) on a copy of the committed
    results gives the committed paper_figures/report byte for byte, nothing ignored: no page holds
    a time or a path of the machine. Regenerate it with that command when this fails."""
    shutil.copytree(PAPER_FIGURES, tmp_path / "paper_figures", ignore=shutil.ignore_patterns("report"))
    r = subprocess.run([binary, "report", "--out", "paper_figures"], capture_output=True, text=True, cwd=tmp_path)
    assert r.returncode == 0, r.stderr
    committed, fresh = os.path.join(PAPER_FIGURES, "report"), tmp_path / "paper_figures" / "report"
    assert sorted(os.listdir(fresh)) == sorted(os.listdir(committed))
    for n in os.listdir(committed):
        with open(os.path.join(committed, n), "rb") as a, open(fresh / n, "rb") as b:
            assert a.read() == b.read(), f"paper_figures/report/{n} differs from what the code writes now"


# ---------------------------------------------------------------- issue 41: the report as a referee reads it


def check_all_headline(binary, out, cwd=None) -> list[str]:
    """The headline lines `granrepro check --all` prints after its tables: per paper its line and
    its 'not in the headline' line, then the totals."""
    r = subprocess.run([binary, "check", "--all", "--missing-ok", "--out", str(out)], capture_output=True, text=True,
                       cwd=cwd)
    assert r.returncode in (0, 1), r.stderr
    lines = [line for line in r.stdout.splitlines() if line and not line.startswith((" ", "check ", "("))]
    assert lines and lines[-1].startswith("totals: "), r.stdout[-2000:]
    return lines


def headline_on(index: str) -> list[str]:
    """The text of the summary page's headline lines, in page order."""
    return [html.unescape(re.sub(r"<[^>]+>", "", m))
            for m in re.findall(r'<p class="headline-line[^"]*">(.*?)</p>', index, re.S)]


def deviation_boxes(text: str) -> dict:
    """claim id -> (first sentence, the rest of the box) of each deviation box of a page."""
    out = {}
    for anchor, box in re.findall(r'<div class="deviation" id="dev-claim-[^"]*?--([^"]+)">(.*?)\n</div>', text, re.S):
        first = re.match(r'\s*<p class="gist"><span class="gist-text">(.*?)</span>', box, re.S)
        assert first, box[:300]
        out[anchor] = (html.unescape(first.group(1)), box[first.end():])
    return out


@pytest.fixture(scope="module")
def paper_report(binary, tmp_path_factory):
    """A copy of the committed paper_figures (its report left out), with `granrepro report --out
    paper_figures` and `check --all --explain` run in it as a reader would."""
    root = tmp_path_factory.mktemp("paper")
    shutil.copytree(PAPER_FIGURES, root / "paper_figures", ignore=shutil.ignore_patterns("report"))
    r = subprocess.run([binary, "report", "--out", "paper_figures"], capture_output=True, text=True, cwd=root)
    assert r.returncode == 0, r.stderr
    return root


def test_the_summary_opens_with_the_headline_check_all_prints(binary, paper_report):
    index = page(paper_report / "paper_figures" / "report" / "index.html")
    expected = check_all_headline(binary, "paper_figures", cwd=paper_report)
    shown = headline_on(index)
    assert sorted(shown) == sorted(expected)
    # the papers' headlines first, in check's order; the other roles apart, after them; the totals last
    papers = [line for line in expected if " statements \u2014 " in line]
    assert shown[:len(papers)] == papers and shown[-1] == expected[-1]
    assert index.index('class="headline-line') < index.index("<h2>")  # it opens the page
    assert index.index('<div class="not-headline">') < index.index(", not in the headline: ")


def test_the_headline_of_quick_runs_is_check_s_too(binary, quick_out, tmp_path):
    r = report(binary, quick_out, tmp_path / "report")
    assert r.returncode == 0, r.stderr
    assert sorted(headline_on(page(tmp_path / "report" / "index.html"))) == sorted(check_all_headline(binary, quick_out))


def test_each_deviation_box_opens_with_what_differs_by_how_much_and_its_status(binary, paper_report):
    # check --explain names each DEVIATION's band and status; its table the measured value
    r = subprocess.run([binary, "check", "--all", "--explain", "--out", "paper_figures"], capture_output=True,
                       text=True, cwd=paper_report)
    explained = {}
    experiment = None
    for line in r.stdout.splitlines():
        if line.startswith("check "):
            experiment = line.split()[1]
            measured = {}
        elif line.startswith("  claim "):  # the table's header: where its measured column is
            columns = (line.index("measured"), line.index("tolerance (kind)"))
        elif line.startswith("  ") and line.endswith("DEVIATION"):
            measured[line.split()[0]] = line[columns[0]:columns[1]].strip()
        m = re.match(r"  (\S+) \(DEVIATION, band (\[[^\]]*\])\):$", line)
        if m:
            explained[(experiment, m.group(1))] = [m.group(2), measured[m.group(1)], None]
        m = re.match(r"      known deviation \((\w+)\): ", line)
        if m:
            explained[list(explained)[-1]][2] = m.group(1)
    deviations = int(re.search(r"^totals: \d+ PASS, 0 FAIL, (\d+) DEVIATION", r.stdout, re.M).group(1))
    assert len(explained) == deviations > 0  # every DEVIATION of paper_figures
    for (exp, cid), (band, measured, status) in explained.items():
        first, rest = deviation_boxes(page(paper_report / "paper_figures" / "report" / f"{exp}.html"))[cid]
        assert first.startswith(f"{cid}: measured {measured} against the paper's "), first
        assert f"band {band}" in first and first.endswith(f"; {status}."), first
        assert status in ("settled", "inherent", "open")
        # the long text folded below it
        assert re.match(r'\s*<span class="verdict deviation">DEVIATION</span></p>\s*<p class="runs">[^\n]*</p>\s*<details>',
                        rest), rest[:300]


def test_a_deviation_sentence_from_the_claims_fields(quick_out, tmp_path):
    results = copy_run(quick_out, tmp_path)
    judged = judged_of(results, "brake-failure", id="normal_branch_k200000", measured=0.8, expected="0.7",
                       tolerance="abs 0.05", deviation_band="[0.75, 0.85]", status="open", verdict="DEVIATION",
                       known_deviation="One grid step off (aef77da).", role="reproduction")
    make_report(str(results), judged, str(tmp_path / "report"), warn=lambda m: None)
    text = page(tmp_path / "report" / "brake-failure.html")
    first, rest = deviation_boxes(text)["normal_branch_k200000"]
    assert first == "normal_branch_k200000: measured 0.8 against the paper's 0.7 ± 0.05 (0.1 above, +14%; " \
                    "band [0.75, 0.85]); open."
    details = rest[rest.index("<details>"):]
    assert "One grid step off (aef77da)." in details  # folded
    # which runs the text is about: the results' code version, and the commit the text names
    with open(results / "brake-failure" / "summary.json") as f:
        version = json.load(f)["code_version"]
    runs = rest[:rest.index("<details>")]
    assert f"code version <code>{version}</code>" in runs and "names commit <code>aef77da</code>" in runs, runs


def test_claims_judged_before_issue_41_still_render(quick_out, tmp_path):
    results = copy_run(quick_out, tmp_path)
    judged = judged_of(results, "brake-failure")
    for c in judged["experiments"][0]["claims"]:
        c.pop("role", None)
        c.pop("status", None)
    model = make_report(str(results), judged, str(tmp_path / "report"), warn=lambda m: None)
    assert all(c.role_shown == "—" for c in model["claims"])
    index = page(tmp_path / "report" / "index.html")
    assert '<span class="role none">—</span>' in index and "No headline: the claims carry no role" in index
    assert headline_on(index) == [f"totals: {model['totals']['PASS']} PASS, {model['totals']['FAIL']} FAIL, "
                                  f"{model['totals']['DEVIATION']} DEVIATION, {model['totals']['skipped']} skipped"]


def test_roles_and_statuses_are_shown_and_filtered(binary, paper_report):
    index = page(paper_report / "paper_figures" / "report" / "index.html")
    rows = re.findall(r'<tr class="(v-[a-z]+ r-[a-z]+(?: s-[a-z]+)?)">', index)
    counts = [[int(n) for n in re.findall(r"(\d+) (?:statements|open)\b", line)]
              for line in check_all_headline(binary, "paper_figures", cwd=paper_report) if " statements " in line]
    # each claim's row carries its role and, for a DEVIATION, its status: counted as check counts them
    assert sum("r-reproduction" in r and "v-skipped" not in r for r in rows) == sum(n for n, _ in counts)
    assert sum("r-reproduction s-open" in r for r in rows) == sum(o for _, o in counts) > 0
    assert all("r-none" not in r for r in rows) and len(rows) == index.count('<span class="role ')
    for option in ('value="r-identity"', 'value="r-calibration"', 'value="v-deviation"', 'value="s-open"'):
        assert option in index, option


def test_a_cited_table_appears_once_per_page(paper_report):
    report_dir = paper_report / "paper_figures" / "report"
    for name in os.listdir(report_dir):
        if not name.endswith(".html"):
            continue
        text = page(report_dir / name)
        shown = re.findall(r'<figure class="table" id="[^"]+">\s*<figcaption><code>tables/([^<]+)\.tsv', text)
        assert len(shown) == len(set(shown)), (name, shown)
        for anchor in re.findall(r'It cites <a href="#([^"]+)">', text):
            assert f'<figure class="table" id="{anchor}">' in text, (name, anchor)
    bistable = page(report_dir / "bistable-pipe.html")
    assert bistable.count("It cites <a href=") >= 3  # steady_k2000 is cited by four boxes, shown in one
