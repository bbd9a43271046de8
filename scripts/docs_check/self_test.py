"""Made-up pages the check must pass, and disagreements it must report."""
import json
import pathlib
import re
import sys
import tempfile

from .numerals import agrees, parse_numbers
from .pages import run

SELF_TEST_CSV = """mu0,phi,regime,eta,eta_err,frac,note
0.1,0.60761,cst,50912.3,3140,0.2326,
0.4,0.57807,dst (uncertain),1547.2,,0.0,blow-up at step 143039
"""
SELF_TEST_RAMPS = """lambda,s_c,eta
1,5e-06,114.3
1,5e-05,106.2
3,5e-06,92.0
3,5e-05,95.45
"""

AGREE = """# made up
<!-- table-source: d/t.csv key=mu0 columns="mu0 | phi | regime | eta eta_err? | frac*100 | -" -->
| mu0 | phi | regime | eta | unconverged | comment |
|---|---|---|---|---|---|
| 0.4 | 0.578 | `dst (uncertain)` | 1,547 | 0% | anything 12 |
| 0.1 | 0.6076 | cst | 50,900 ± 3,100 | 23% | |

<!-- table-source: d/s.csv key=lambda
     columns="lambda | eta[s_c=5e-06] | eta[s_c=5e-05]" -->

| lambda | eta (s_c 5e-6) | eta (s_c 5e-5) |
|---|---|---|
| 3 | 92 | 95.5 |
| 1 | 114 | 106 |

<!-- table-source: d/s.csv where=s_c=5e-05 columns="lambda | eta" -->
| lambda | eta |
|---|---|
| 1 | 1.06 x 10^2 |
| 3 | 95.45 |

<!-- table-source: d/t.json columns="a.b | c" -->
| a.b | c |
|---|---|
| 2.5 | — (none) |

An example in a code block is not read:

    <!-- table-source: d/none.csv columns="x" -->

<!-- value-source: d/t.csv where=mu0=0.4 column=note says="step 143039" -->
It blew up at step 143039, says the file.

<!-- value-source: d/t.csv where=eta>1000 aggregate=count says="2" -->
<!-- value-source: d/t.csv where=regime!=cst column=eta aggregate=max says="1,547" -->
<!-- value-source: d/s.csv where=lambda>=3 column=eta aggregate=max says="95.45" -->
Of the 2 curves above 1000, the one not CST reaches 1,547; from lambda 3 on
no point exceeds 95.45.
"""

# Made-up disagreements: (text in AGREE, what replaces it, what the report must say).
DISAGREE = [
    ("| 0.4 | 0.578 |", "| 0.4 | 0.577 |",
     "docs/x.md:5: column phi, row mu0 0.4: docs say 0.577, CSV says 0.57807"),
    ("| `dst (uncertain)` |", "| `dst` |",
     "column regime, row mu0 0.4: docs say dst, CSV says dst (uncertain)"),
    ("| 1,547 |", "| 1,557 |", "column eta, row mu0 0.4: docs say 1557, CSV says 1547.2"),
    ("| 23% |", "| 24% |", "column unconverged, row mu0 0.1: docs say 24, CSV says 23.26"),
    ("| 3 | 92 | 95.5 |", "| 3 | 92 | 95.3 |",
     "column eta (s_c 5e-5), row lambda 3: docs say 95.3, CSV says 95.45"),
    ("| 1 | 1.06 x 10^2 |", "| 1 | 1.07 x 10^2 |", "column eta, row 1: docs say 107, CSV says 106.2"),
    ("| 3 | 95.45 |\n", "| 3 | 95.45 |\n| 10 | 169 |\n", "the table has 3 rows, d/s.csv has 2"),
    ("| — (none) |", "| 7 |", "column c, row 1: docs say 7, CSV says (empty)"),
    ("at step 143039, says", "at step 1114, says",
     "the paragraph below the marker does not say 'step 143039'"),
    ("column=note", "column=notes", "d/t.csv has no column 'notes'"),
    ("d/t.json", "d/missing.json", "marker names d/missing.json, which does not exist"),
    ("| 0.1 | 0.6076 |", "| 0.2 | 0.6076 |", "no rows of d/t.csv match row mu0 0.2"),
    ("| 50,900 ± 3,100 |", "| 50,900 ± 3,100 (4) |", "where the cell shows 3 number(s)"),
    ("key=lambda\n     columns=\"lambda | eta[s_c=5e-06]", "key=lambda\n     columns=\"lambda | eta",
     "2 rows of d/s.csv match row lambda 3"),
    ('columns="a.b | c"', 'columns="a.b"', "the table has 2 columns, the marker's columns= 1"),
    ("where=eta>1000 aggregate", "where=eta>10000 aggregate",
     "count of the rows eta>10000: docs say 2, CSV says 1"),
    ("where=lambda>=3 column", "where=lambda>=1 column", "max of column eta over the rows lambda>=1: docs say 95.45, CSV says 114.3"),
    ("regime!=cst column=eta aggregate=max", "regime!=cst column=eta aggregate=median",
     "aggregate=median: not one of count, min, max"),
    ("where=eta>1000", "where=eta>high", "compares with 'high', not a number"),
    ("where=regime!=cst column=eta", "where=regime=none column=eta",
     "where= selects no row of d/t.csv to take the max of"),
]


def self_test():
    failures = []
    with tempfile.TemporaryDirectory() as tmp:
        root = pathlib.Path(tmp)
        (root / "d").mkdir()
        (root / "docs").mkdir()
        (root / "d/t.csv").write_text(SELF_TEST_CSV)
        (root / "d/s.csv").write_text(SELF_TEST_RAMPS)
        (root / "d/t.json").write_text(json.dumps({"a": {"b": 2.5}, "c": None}))
        (root / "docs/x.md").write_text(AGREE)
        problems, guarded = run(root, ["docs"])
        if problems or guarded != 8:
            failures.append(f"agreeing docs: {guarded} markers, problems {problems}")
        for old, new, expected in DISAGREE:
            if old not in AGREE:
                failures.append(f"the self-test's page has no '{old}'")
                continue
            (root / "docs/x.md").write_text(AGREE.replace(old, new, 1))
            problems, _ = run(root, ["docs"])
            if not any(expected in p for p in problems):
                failures.append(f"'{new}' not reported as '{expected}': {problems}")
            elif not all(re.match(r"docs/x\.md:\d+: ", p) for p in problems):
                failures.append(f"a problem without its file and line: {problems}")
        # Stacked markers: each `says` must be in the paragraph's own words,
        # not in the marker below it.
        stacked = AGREE.replace(
            '<!-- value-source: d/t.csv where=mu0=0.4 column=note says="step 143039" -->\n',
            '<!-- value-source: d/t.csv where=mu0=0.4 column=note says="step 143039" -->\n' * 2)
        (root / "docs/x.md").write_text(stacked.replace("at step 143039, says", "at step 1114, says"))
        problems, _ = run(root, ["docs"])
        if sum("does not say 'step 143039'" in p for p in problems) != 2:
            failures.append(f"a stacked marker answered for the one above it: {problems}")
        # A number the docs round is not a disagreement; one they change is.
        roundings = [("0.6355", 0.63555, True), ("6.9e-4", 6.95e-4, True),
                     ("195,000", 194_873, True), ("338", 338.4, True),
                     ("0.0116", 0.01157, True), ("0.0117", 0.01157, False),
                     ("-0.11", -0.1104, True), ("+0.12", 0.12, True),
                     ("4 x 10^4", 40000.0, True), ("1.8", 1.86, False)]
        for docs, csv_value, ok in roundings:
            (v, h), = parse_numbers(docs)
            if agrees(v, h, csv_value) != ok:
                failures.append(f"{docs} against {csv_value}: expected {'agree' if ok else 'differ'}")
        if [v for v, _ in parse_numbers("0.1-0.4")] != [0.1, 0.4] or len(parse_numbers("n 1 in x20,000")) != 2:
            failures.append(f"ranges or words read wrong: {parse_numbers('0.1-0.4')}")
    for f in failures:
        print(f"self-test: {f}", file=sys.stderr)
    print(f"self-test: {'FAILED' if failures else 'passed'} "
          f"(an agreeing page, {len(DISAGREE)} made-up disagreements, {len(roundings)} roundings)")
    return 1 if failures else 0
