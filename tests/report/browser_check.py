"""The report in a real browser: `granrepro report` on a results folder, then headless Chromium
(Debian `chromium`) loads every page. Fails on a console message (a script error), a local href
or src that does not resolve (file, or #anchor in its page), an image that is not a PNG/JPEG/SVG
file, or a figure the report lists as missing; requires the summary page to open with the headline
`granrepro check --all` prints for the same folder, as rendered text the reader sees (issue 41), and
no page to be wider than a 1024-pixel window with every <details> open (wide tables scroll inside
their box); saves screenshots of the
summary and of one figure section into --work. --self-test then breaks one image path in a copy of a page and
requires this check to fail on it.

    browser_check.py --binary build/granrepro --results paper_figures --work build/report-browser
"""
from __future__ import annotations

import argparse
import concurrent.futures
import html.parser
import os
import re
import shutil
import subprocess
import sys
import urllib.parse


class Page(html.parser.HTMLParser):
    def __init__(self):
        super().__init__()
        self.links = []  # (tag, attribute, value)
        self.ids = set()
        self.missing_figures = 0

    def handle_starttag(self, tag, attrs):
        a = dict(attrs)
        if "id" in a:
            self.ids.add(a["id"])
        for k in ("href", "src"):
            if a.get(k) is not None:
                self.links.append((tag, k, a[k]))
        if "missing-figure" in (a.get("class") or "").split():
            self.missing_figures += 1


def parse(text: str) -> Page:
    p = Page()
    p.feed(text)
    return p


def chromium() -> str:
    for name in ("chromium", "chromium-browser", "google-chrome"):
        path = shutil.which(name)
        if path:
            return path
    sys.exit("browser_check: no chromium found (Debian: apt-get install chromium; scripts/setup.sh installs it)")


def browser(args: list[str], profile: str) -> subprocess.CompletedProcess:
    cmd = [chromium(), "--headless", "--disable-gpu", "--hide-scrollbars", "--no-first-run",
           f"--user-data-dir={profile}", "--enable-logging=stderr", "--v=0", *args]
    if os.geteuid() == 0:
        cmd.insert(1, "--no-sandbox")
    return subprocess.run(cmd, capture_output=True, text=True, timeout=120)


IMAGE_MAGIC = (b"\x89PNG\r\n\x1a\n", b"\xff\xd8\xff")


def check_page(page: str, work: str, n: int) -> list[str]:
    """Loads one page; returns the problems found."""
    problems = []
    url = "file://" + urllib.parse.quote(os.path.abspath(page))
    r = browser(["--dump-dom", url], os.path.join(work, f"profile-{n}"))
    name = os.path.basename(page)
    for line in r.stderr.splitlines():
        if ":CONSOLE" in line:
            problems.append(f"{name}: console: {line.split('] ', 1)[-1]}")
    if r.returncode != 0 or "<html" not in r.stdout:
        problems.append(f"{name}: chromium exited {r.returncode} without a DOM")
        return problems
    dom = parse(r.stdout)
    if dom.missing_figures:
        problems.append(f"{name}: {dom.missing_figures} figure(s) listed as missing")
    here = os.path.dirname(os.path.abspath(page))
    for tag, attr, value in dom.links:
        u = urllib.parse.urlsplit(value)
        if u.scheme and u.scheme != "file":
            problems.append(f"{name}: <{tag} {attr}={value!r}> leaves the report (no network allowed)")
            continue
        target = os.path.normpath(os.path.join(here, urllib.parse.unquote(u.path))) if u.path else os.path.abspath(page)
        if not os.path.isfile(target):
            problems.append(f"{name}: <{tag} {attr}={value!r}>: {target} does not exist")
            continue
        if tag == "img":
            with open(target, "rb") as f:
                head = f.read(8)
            if not (head.startswith(IMAGE_MAGIC) or target.endswith(".svg")):
                problems.append(f"{name}: <img src={value!r}>: not a PNG or JPEG file")
        if u.fragment and target.endswith(".html"):
            with open(target, encoding="utf-8") as f:
                if u.fragment not in parse(f.read()).ids:
                    problems.append(f"{name}: <{tag} {attr}={value!r}>: no id {u.fragment!r} in {os.path.basename(target)}")
    return problems


def check_report(report: str, work: str) -> list[str]:
    pages = sorted(os.path.join(report, p) for p in os.listdir(report) if p.endswith(".html"))
    if not any(p.endswith("index.html") for p in pages):
        return [f"{report}: no index.html"]
    with concurrent.futures.ThreadPoolExecutor(max_workers=2) as pool:
        found = pool.map(lambda ip: check_page(ip[1], work, ip[0]), enumerate(pages))
    return [p for ps in found for p in ps]


def screenshots(report: str, work: str) -> list[str]:
    """The summary and the first figure section that has an image."""
    shots = [("screenshot-summary.png", os.path.join(report, "index.html"), "")]
    for page in sorted(os.listdir(report)):
        if page.endswith(".html") and page != "index.html":
            with open(os.path.join(report, page), encoding="utf-8") as f:
                m = re.search(r'<section id="([^"]+)">\s*<h2>[^<]*<span[^>]*>[^<]*</span></h2>\s*<blockquote>.*?<img ',
                              f.read(), re.S)
            if m:
                shots.append(("screenshot-figure.png", os.path.join(report, page), m.group(1)))
                break
    problems = []
    for name, page, fragment in shots:
        out = os.path.join(work, name)
        url = "file://" + urllib.parse.quote(os.path.abspath(page)) + (f"#{fragment}" if fragment else "")
        r = browser(["--window-size=1280,1400", f"--screenshot={out}", url], os.path.join(work, "profile-shot"))
        if not os.path.isfile(out) or os.path.getsize(out) < 10000:
            problems.append(f"screenshot {name} of {url} not written (chromium exited {r.returncode})")
        else:
            print(f"browser_check: {out} ({url})")
    return problems


PROBE = """<script>
window.addEventListener("load", function () {
  const seen = [];
  for (const e of document.querySelectorAll(".headline-line")) {
    const r = e.getBoundingClientRect(), style = getComputedStyle(e);
    seen.push({text: e.innerText, visible: r.width > 0 && r.height > 0 && style.visibility === "visible"
               && style.display !== "none" && parseFloat(style.opacity) > 0, top: r.top + window.scrollY});
  }
  for (const d of document.querySelectorAll("details")) d.open = true;  // the folded tables too
  const out = document.createElement("pre");
  out.id = "browser-check-probe";
  out.textContent = JSON.stringify({lines: seen, scrollWidth: document.documentElement.scrollWidth,
                                    width: window.innerWidth});
  document.body.appendChild(out);
});
</script>"""


def probe(page: str, work: str, width: int = 1024) -> dict:
    """What the reader sees on a page: the headline lines (their rendered text, visible or not, how far
    down) and the page's width, measured by a script in a copy of the page beside it."""
    copy = os.path.join(os.path.dirname(page), ".probe-" + os.path.basename(page))
    with open(page, encoding="utf-8") as f:
        text = f.read()
    with open(copy, "w", encoding="utf-8") as f:
        f.write(text.replace("</body>", PROBE + "</body>"))
    try:
        url = "file://" + urllib.parse.quote(os.path.abspath(copy))
        r = browser([f"--window-size={width},1400", "--dump-dom", url], os.path.join(work, "profile-probe"))
    finally:
        os.remove(copy)
    m = re.search(r'<pre id="browser-check-probe">(.*?)</pre>', r.stdout, re.S)
    if not m:
        return {}
    import html as html_module
    import json
    return json.loads(html_module.unescape(m.group(1)))


def check_headline(binary: str, results: str, report: str, work: str) -> list[str]:
    """The summary opens with check --all's headline lines (each visible, as rendered text, within the
    first screen), and no page is wider than a 1024-pixel window, its folded parts open."""
    r = subprocess.run([binary, "check", "--all", "--missing-ok", "--out", results], capture_output=True, text=True)
    expected = [line for line in r.stdout.splitlines() if line and not line.startswith((" ", "check ", "("))]
    if not expected or not expected[-1].startswith("totals: "):
        return [f"check --all --out {results} printed no headline (exit {r.returncode}): {r.stderr.strip()[:300]}"]
    problems = []
    seen = probe(os.path.join(report, "index.html"), work)
    if not seen:
        return ["index.html: the probe script did not run"]
    lines = seen["lines"]
    shown = [x["text"].strip() for x in lines]
    if sorted(shown) != sorted(expected):
        problems.append(f"index.html: the headline shown {shown} is not check --all's {expected}")
    problems += [f"index.html: headline line {x['text']!r} is not visible" for x in lines if not x["visible"]]
    problems += [f"index.html: headline line {x['text']!r} is {x['top']:.0f} px down, below the first screen"
                 for x in lines if x["top"] > 1400]
    if not problems:
        print(f"browser_check: index.html shows check --all's headline: {' | '.join(shown)}")
    for page in sorted(os.listdir(report)):
        if page.endswith(".html") and not page.startswith("."):
            p = seen if page == "index.html" else probe(os.path.join(report, page), work)
            if p and p["scrollWidth"] > p["width"]:
                problems.append(f"{page}: {p['scrollWidth']} px wide in a {p['width']} px window (a table that "
                                "does not scroll inside its box)")
    return problems


def self_test(report: str, work: str) -> list[str]:
    """A copy of the report with one image path broken must fail the check."""
    copy = os.path.join(work, "broken-report")
    shutil.rmtree(copy, ignore_errors=True)
    shutil.copytree(report, copy, symlinks=True)
    for page in sorted(os.listdir(copy)):
        path = os.path.join(copy, page)
        if not page.endswith(".html"):
            continue
        text = open(path, encoding="utf-8").read()
        broken, n = re.subn(r'<img src="([^"]+)"', r'<img src="\1.broken"', text, count=1)
        if n:
            # the copy sits beside the report, so a relative path into the results folder still resolves
            open(path, "w", encoding="utf-8").write(broken)
            found = check_page(path, work, 99)
            if not any(".broken" in p and "does not exist" in p for p in found):
                return [f"self-test: a broken image path in {page} was not found: {found}"]
            print(f"browser_check: self-test: a broken image path in {page} is found: {found[0]}")
            return []
    return ["self-test: no page with an image"]


def main() -> int:
    ap = argparse.ArgumentParser()
    ap.add_argument("--binary", required=True)
    ap.add_argument("--results", required=True)
    ap.add_argument("--work", required=True, help="scratch folder: the report, profiles, screenshots")
    ap.add_argument("--self-test", action="store_true")
    a = ap.parse_args()
    shutil.rmtree(a.work, ignore_errors=True)
    os.makedirs(a.work)
    report = os.path.join(a.work, "report")
    r = subprocess.run([a.binary, "report", "--out", a.results, "--to", report], capture_output=True, text=True)
    print(r.stdout + r.stderr, end="")
    if r.returncode != 0:
        print(f"browser_check: granrepro report exited {r.returncode}", file=sys.stderr)
        return 1
    problems = check_report(report, a.work) + check_headline(a.binary, a.results, report, a.work) \
        + screenshots(report, a.work)
    if a.self_test and not problems:
        problems += self_test(report, a.work)
    for p in problems:
        print(f"browser_check: {p}", file=sys.stderr)
    print(f"browser_check: {report}: {'FAILED, ' + str(len(problems)) + ' problems' if problems else 'every page loads cleanly'}")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
