# expected/STATEMENTS.md lists every statement of the two papers that carries a number or a
# relation, with the `reproduction` claims of expected/*.toml that test it or the reason it cannot
# be checked (issue 41 item 1). Checked here: every claim id it names exists and, in the claims
# column, has role `reproduction`; every row names a claim or gives a reason; every `reproduction`
# claim of expected/ answers to some row.
import glob
import os
import re
import tomllib

import pytest

ROOT = os.path.join(os.path.dirname(__file__), "..", "..")
EXPECTED = os.path.join(ROOT, "expected")
STATEMENTS = os.path.join(EXPECTED, "STATEMENTS.md")
GAPS = "Gaps: statements without a claim"
EMPTY = {"", "—", "-"}


def claims():
    """{claim id: (role, file)} over expected/*.toml."""
    out = {}
    for path in sorted(glob.glob(os.path.join(EXPECTED, "*.toml"))):
        with open(path, "rb") as f:
            data = tomllib.load(f)
        for claim in data.get("claim", []):
            out.setdefault(claim["id"], []).append((claim["role"], os.path.basename(path)))
    return out


def experiment_papers():
    """The papers of experiments/*.toml (their `paper` field), sorted, each once."""
    papers = set()
    for path in glob.glob(os.path.join(ROOT, "experiments", "*.toml")):
        with open(path, "rb") as f:
            papers.add(tomllib.load(f)["paper"])
    return sorted(papers)


def cells(line):
    """The cells of a markdown table row, with `|` inside backticks kept."""
    parts, cur, tick = [], "", False
    for ch in line.strip()[1:-1] if line.strip().endswith("|") else line.strip()[1:]:
        if ch == "`":
            tick = not tick
        if ch == "|" and not tick:
            parts.append(cur.strip())
            cur = ""
        else:
            cur += ch
    parts.append(cur.strip())
    return parts


def tables():
    """{section title: [(line number, [cells])]} for the table rows (header and rule excluded)."""
    out, section, header_seen = {}, None, False
    with open(STATEMENTS) as f:
        for n, line in enumerate(f, 1):
            if line.startswith("## "):
                section, header_seen = line[3:].strip(), False
                out[section] = []
                continue
            if section is None or not line.lstrip().startswith("|"):
                header_seen = False
                continue
            row = cells(line)
            if not header_seen:
                header_seen = True  # the header row
                continue
            if all(re.fullmatch(r":?-+:?", c) for c in row):
                continue
            out[section].append((n, row))
    return out


def paper_rows():
    return [(title, n, row) for title, rows in tables().items() if title != GAPS for n, row in rows]


def ids(cell):
    return re.findall(r"`([^`]+)`", cell)


def test_structure():
    t = tables()
    papers = [title for title in t if title != GAPS]
    # one table per paper, titled with the paper as experiments/<name>.toml names it
    assert sorted(papers) == experiment_papers(), f"{STATEMENTS}: the tables are not the papers of experiments/*.toml"
    assert GAPS in t, f"no section '## {GAPS}'"
    for title, n, row in paper_rows():
        assert len(row) == 4, f"STATEMENTS.md:{n} ({title}): {len(row)} cells, want 4: {row}"
        assert row[0] not in EMPTY and row[1] not in EMPTY, f"STATEMENTS.md:{n}: no where or statement"


def test_every_row_has_a_claim_or_a_reason():
    bad = [f"STATEMENTS.md:{n}: {row[1]}" for _, n, row in paper_rows()
           if not ids(row[2]) and row[3] in EMPTY]
    assert not bad, "rows with neither a reproduction claim nor a reason:\n" + "\n".join(bad)


def test_named_claims_exist():
    known = claims()
    bad = [f"STATEMENTS.md:{n}: `{i}`" for _, n, row in paper_rows()
           for i in ids(row[2]) + ids(row[3]) if i not in known]
    assert not bad, "claim ids that expected/*.toml does not define:\n" + "\n".join(bad)


def test_claims_column_is_reproduction_only():
    known = claims()
    bad = [f"STATEMENTS.md:{n}: `{i}` is {known[i]}" for _, n, row in paper_rows()
           for i in ids(row[2]) if i in known and any(r != "reproduction" for r, _ in known[i])]
    assert not bad, "claims column names claims whose role is not reproduction:\n" + "\n".join(bad)


def test_every_reproduction_claim_answers_to_a_statement():
    named = {i for _, _, row in paper_rows() for i in ids(row[2])}
    missing = sorted(f"{files[0][1]}: {i}" for i, files in claims().items()
                     if any(r == "reproduction" for r, _ in files) and i not in named)
    assert not missing, "reproduction claims named by no statement:\n" + "\n".join(missing)


def test_gaps_have_no_claim():
    """A gap row proposes a claim; it must not name one that already exists as a reproduction."""
    known = claims()
    for n, row in tables().get(GAPS, []):
        assert len(row) == 4 and row[3] not in EMPTY, f"STATEMENTS.md:{n}: a gap needs a proposed claim"
        for i in ids(row[3]):
            assert i not in known, f"STATEMENTS.md:{n}: gap names existing claim `{i}`"


if __name__ == "__main__":
    raise SystemExit(pytest.main([__file__, "-q"]))
