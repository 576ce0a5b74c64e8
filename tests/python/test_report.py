# granrepro report (python/granrepro/report) on quick-scale runs of brake-failure and
# emergency-brake: every claim appears exactly once, every text is escaped, a missing figure is
# reported, bad input exits 2 with one line, and a report replaces the previous one whole.
import json
import os
import re
import shutil
import subprocess

import pytest

from granrepro.report import BadInput, make_report


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
