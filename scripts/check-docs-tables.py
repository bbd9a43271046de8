#!/usr/bin/env python3
"""Checks that the results tables and numbers of docs/*.md agree with the
committed files they were copied from.

A docs table copied from a CSV (or JSON) file carries a marker, an HTML comment
that starts a line just above it (blank lines between are allowed; an indented
marker is an example in a code block and is not read). Its arguments are
read like a shell command line (quote an argument that holds spaces):

    <!-- table-source: docs/jamming/phi_max_bl.csv key=mu0
         columns="mu0 | phi_max phi_max_err | max_overlap | -" -->
    | mu0 | phi_max_BL | largest overlap (R) | wall time (s) |
    |---|---|---|---|
    | 0.4 | 0.5781 ± 0.0006 | 6.9e-4 | 480 |

* FILE (first argument): a path from the repository's root. A .csv file's rows
  are its rows; a .json file holding a list of objects gives one row each, a
  single object one row (nested keys joined with dots: `stress.mu_eff`).
  Several files joined by commas give their rows in that order (one
  `summary.json` per table row).
* `columns="SPEC | SPEC | ..."`: one SPEC per column of the table, in order.
  A SPEC is `-` (the column is not from this file: not checked) or the file's
  columns whose values the cell shows, in the order the cell shows them,
  separated by spaces. The numbers of the cell (`0.5781 ± 0.0006` holds two)
  are compared one by one with them, and the cell must hold exactly as many
  numbers as the SPEC names columns. In a SPEC:
    - `_` stands for a number of the cell that is not from the file (`_?`:
      one that may be missing);
    - `NAME?` may be missing from the cell (`eta eta_err?` reads `112` and
      `112 ± 8`; an empty cell of only `?` names says nothing against the file);
    - `NAME*100` compares the file's value times 100 (a fraction shown in %);
    - `NAME[COL=VALUE,...]` takes NAME from the row that also has those
      values (two curves of one file side by side in one table).
* `key=COL[,COL...]`: the columns that identify a row. Each must begin a
  SPEC of `columns` (`phi phi_bulk` keys on phi, the cell's first number, and
  checks phi_bulk); a table row's key cells select the file's row
  whose values equal them (or, if none is equal, agree with them as numbers
  rounded, below). Without `key`, the table's rows are the
  file's rows (after `where`) in order, and their numbers must be equal.
* `where=COL=VALUE` (may be repeated): only the file's rows with that value
  are considered. `COL!=VALUE` keeps the rows without it; `COL<VALUE`,
  `COL<=VALUE`, `COL>VALUE`, `COL>=VALUE` compare numbers (a row whose value
  is not a number is left out). The same conditions go in `NAME[..]`.

Numbers agree when the file's value, rounded to the digits the docs cell
shows, is the docs value: |docs - file| <= half a unit of the docs number's
last digit (`0.6355` allows 5e-5, `6.9e-4` allows 5e-6, `338` allows 0.5).
An integer's trailing zeros are read as rounding (`50,900` allows 50,
`195,000` allows 500); `1,215` is one number. `10^4` and `4 x 10^4` are
numbers. A cell that is empty or begins with a dash (`—`, `–`, `-` and a space)
says "no value": the file's values must be empty too. A cell without numbers
whose SPEC is one column of text (`dst (uncertain)`) must equal the file's
text exactly (`**` and backticks aside).

A number in prose carries a marker of its own, just above its paragraph:

    <!-- value-source: docs/jamming/shear-flowcurves.csv where=cell.phi=0.64
         where=friction.mu0=1 column=error says="step 143039" -->

`column` names one column of the one row that the `where`s select (a JSON key
that holds spaces is quoted whole: `column="samples.mu0=0.5 seed=1.phi_0"`); `says` is
text that must appear in the paragraph below the marker (up to the next blank
line) and agree with that value: as a number (rounded as above) if it is one,
else as a part of the file's text.

A count or a range in prose (how many points, the least and greatest of
them) takes `aggregate=count`, `aggregate=min` or `aggregate=max`: the
`where`s may then select any number of rows, and the value is how many they
are (no `column` needed), or the least or greatest of `column` over them:

    <!-- value-source: docs/paper-reproduction/rate-intermittency/intermittency.csv
         where=slow_intervals=0 aggregate=count says="76" -->

Exits 1 with one line per disagreement,
`docs/X.md:LINE: column C, row K: docs say A, CSV says B`, and also when a
marker names a file or column that does not exist or selects no row.

    python3 scripts/check-docs-tables.py [DOCS_DIR ...]   (default: docs/)
    python3 scripts/check-docs-tables.py --self-test      (agreeing and disagreeing made-up docs)
    python3 scripts/check-docs-tables.py --list           (the guarded tables and values)

The parts are in scripts/docs_check/ (its __init__.py lists them).
"""
import pathlib
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
from docs_check.pages import run  # noqa: E402  (the package sits beside this script)
from docs_check.self_test import self_test  # noqa: E402

ROOT = pathlib.Path(__file__).resolve().parent.parent


def main(argv):
    if "--self-test" in argv:
        return self_test()
    listing = [] if "--list" in argv else None
    dirs = [a for a in argv if not a.startswith("--")] or ["docs"]
    problems, guarded = run(ROOT, dirs, listing)
    for line in listing or []:
        print(line)
    for p in problems:
        print(p)
    print(f"check-docs-tables: {guarded} markers checked, {len(problems)} disagreement(s)",
          file=sys.stderr)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
