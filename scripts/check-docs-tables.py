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
  are considered.

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

Exits 1 with one line per disagreement,
`docs/X.md:LINE: column C, row K: docs say A, CSV says B`, and also when a
marker names a file or column that does not exist or selects no row.

    python3 scripts/check-docs-tables.py [DOCS_DIR ...]   (default: docs/)
    python3 scripts/check-docs-tables.py --self-test      (agreeing and disagreeing made-up docs)
    python3 scripts/check-docs-tables.py --list           (the guarded tables and values)
"""
import csv
import json
import math
import pathlib
import re
import shlex
import sys
import tempfile

ROOT = pathlib.Path(__file__).resolve().parent.parent

# A marker starts a line: an indented one is an example inside a code block.
MARKER = re.compile(r"^<!--\s*(table-source|value-source):(.*?)-->", re.S | re.M)
TABLE_ROW = re.compile(r"^\s*\|.*\|\s*$")
SEPARATOR = re.compile(r"^\s*\|[\s:|-]+\|\s*$")
# A number as docs write it: 1,215 / -0.11 / +0.12 / 2.3e-4 / 4 x 10^4 / 10^4.
NUMBER = re.compile(
    r"(?<![\w.^])(?P<sign>[-+−]?)"
    r"(?:(?P<mant>\d{1,3}(?:,\d{3})+(?!\d)|\d+(?:\.\d+)?|\.\d+)(?P<exp>[eE][-+]?\d+)?"
    r"(?:\s*[x×]\s*10\^(?P<pow>[-+]?\d+))?"
    r"|10\^(?P<pow2>[-+]?\d+))(?![\w.])")
DASHES = ("—", "–")


class Problem(Exception):
    pass


# ---------------------------------------------------------------- numbers

def parse_numbers(text):
    """The numbers of a docs cell, each as (value, half of its last digit's unit)."""
    out = []
    for m in NUMBER.finditer(text):
        sign = -1.0 if m.group("sign") in ("-", "−") else 1.0
        if m.group("pow2") is not None:
            out.append((sign * 10.0 ** int(m.group("pow2")), 0.0))
            continue
        mant = m.group("mant").replace(",", "")
        exp = int(m.group("exp")[1:]) if m.group("exp") else 0
        if m.group("pow") is not None:
            exp += int(m.group("pow"))
        if "." in mant:
            digits = len(mant.split(".")[1])
            unit = 10.0 ** -digits
        else:
            stripped = mant.rstrip("0")
            trailing = len(mant) - len(stripped) if stripped else 0
            unit = 10.0 ** trailing
        value = sign * float(mant) * 10.0 ** exp
        out.append((value, 0.5 * unit * 10.0 ** exp))
    return out


def to_float(text):
    try:
        v = float(text)
    except (TypeError, ValueError):
        return None
    return v if math.isfinite(v) else None


def agrees(docs_value, half_unit, file_value):
    slack = 1e-9 * max(abs(docs_value), abs(file_value), 1e-300)
    return abs(docs_value - file_value) <= half_unit + slack


def show(v):
    return f"{v:.10g}"


# ---------------------------------------------------------------- files

def flatten(obj, prefix=""):
    if isinstance(obj, dict):
        out = {}
        for k, v in obj.items():
            out.update(flatten(v, f"{prefix}{k}."))
        return out
    if obj is None:
        return {prefix[:-1]: ""}
    if isinstance(obj, bool):
        return {prefix[:-1]: "true" if obj else "false"}
    if isinstance(obj, list):
        return {prefix[:-1]: json.dumps(obj)}
    return {prefix[:-1]: str(obj)}


def read_rows(root, name, cache):
    if "," in name:  # several files: their rows in the order named
        parts = [read_rows(root, n, cache) for n in name.split(",")]
        return ([r for rows, _ in parts for r in rows], set().union(*(c for _, c in parts)))
    if name in cache:
        return cache[name]
    path = root / name
    if not path.is_file():
        raise Problem(f"marker names {name}, which does not exist")
    if path.suffix == ".json":
        data = json.loads(path.read_text())
        rows = [flatten(r) for r in data] if isinstance(data, list) else [flatten(data)]
        columns = set().union(*(r.keys() for r in rows)) if rows else set()
    else:
        with open(path, newline="") as f:
            reader = csv.DictReader(f)
            rows = [dict(r) for r in reader]
            columns = set(reader.fieldnames or [])
    cache[name] = (rows, columns)
    return cache[name]


def value_matches(cell, file_value):
    """Does a marker's VALUE (from where=, key cells, [..]) select file_value?"""
    a, b = to_float(cell), to_float(file_value)
    if a is not None and b is not None:
        return a == b
    return cell.strip() == (file_value or "").strip()


def parse_conditions(text):
    conds = []
    for part in text.split(","):
        if "=" not in part:
            raise Problem(f"cannot read the condition '{part}' (COL=VALUE)")
        col, val = part.split("=", 1)
        conds.append((col.strip(), val.strip()))
    return conds


# ---------------------------------------------------------------- markers

REF = re.compile(r"^(?P<name>[^\[\]*?]+)(?:\[(?P<cond>[^\]]*)\])?(?:\*(?P<factor>[0-9.eE+-]+))?(?P<opt>\?)?$")


def parse_spec(spec):
    spec = spec.strip()
    if spec == "-":
        return None
    refs = []
    for token in spec.split():
        if token in ("_", "_?"):
            refs.append({"skip": True, "optional": token == "_?"})
            continue
        m = REF.match(token)
        if not m:
            raise Problem(f"cannot read '{token}' in columns")
        refs.append({"skip": False, "name": m.group("name"),
                     "cond": parse_conditions(m.group("cond")) if m.group("cond") else [],
                     "factor": float(m.group("factor")) if m.group("factor") else None,
                     "optional": bool(m.group("opt"))})
    return refs


def parse_marker(kind, body):
    try:
        words = shlex.split(body.replace("\n", " "))
    except ValueError as e:
        raise Problem(f"cannot read the marker: {e}")
    if not words:
        raise Problem("the marker names no file")
    marker = {"kind": kind, "file": words[0], "where": [], "key": [], "columns": None,
              "column": None, "says": None}
    for w in words[1:]:
        if "=" not in w:
            raise Problem(f"cannot read '{w}' in the marker")
        opt, val = w.split("=", 1)
        if opt == "where":
            marker["where"] += parse_conditions(val)
        elif opt == "key":
            marker["key"] = [k.strip() for k in val.split(",") if k.strip()]
        elif opt == "columns":
            marker["columns"] = [parse_spec(s) for s in val.split("|")]
        elif opt in ("column", "says"):
            marker[opt] = val
        else:
            raise Problem(f"unknown option '{opt}' in the marker")
    if kind == "table-source" and marker["columns"] is None:
        raise Problem("a table-source marker needs columns=")
    if kind == "value-source" and (marker["column"] is None or marker["says"] is None):
        raise Problem("a value-source marker needs column= and says=")
    return marker


def split_row(line):
    s = line.strip()
    if s.startswith("|"):
        s = s[1:]
    if s.endswith("|"):
        s = s[:-1]
    cells, cur, code = [], "", False
    for ch in s:
        if ch == "`":
            code = not code
        if ch == "|" and not code:
            cells.append(cur.strip())
            cur = ""
        else:
            cur += ch
    cells.append(cur.strip())
    return cells


def plain(text):
    return text.replace("**", "").replace("`", "").strip()


def says_no_value(cell):
    c = plain(cell)
    return c == "" or c.startswith(DASHES) or c == "-" or c.startswith("- ")


def select(rows, conds):
    return [r for r in rows if all(value_matches(v, r.get(c, "")) for c, v in conds)]


# ---------------------------------------------------------------- checks

def check_cell(cell, refs, row_for, report, column_name):
    """Compares one docs cell with the file's values its refs name."""
    values = []
    for ref in refs:
        if ref["skip"]:
            values.append(None)
            continue
        row = row_for(ref)
        values.append(row.get(ref["name"], ""))
    checked = [(r, v) for r, v in zip(refs, values) if not r["skip"]]
    if says_no_value(cell):  # an optional value may be left out of the cell
        present = [v for r, v in checked if (v or "").strip() != "" and not r["optional"]]
        if present:
            report(column_name, cell, " ".join(present))
        return
    numbers = parse_numbers(plain(cell))
    if len(checked) == 1 and not numbers and to_float(checked[0][1]) is None:
        if plain(cell) != (checked[0][1] or "").strip():
            report(column_name, plain(cell), checked[0][1] or "(empty)")
        return
    required = sum(1 for r in refs if not r["optional"])
    if not (required <= len(numbers) <= len(refs)):
        report(column_name, plain(cell),
               f"{len(refs)} value(s) ({', '.join(r.get('name', '_') for r in refs)})"
               f" where the cell shows {len(numbers)} number(s)")
        return
    for (docs_value, half), ref, value in zip(numbers, refs, values):
        if ref["skip"]:
            continue
        f = to_float(value)
        if f is None:
            report(column_name, show_docs(docs_value, half), value or "(empty)")
            continue
        if ref["factor"] is not None:
            f *= ref["factor"]
        if not agrees(docs_value, half, f):
            report(column_name, show_docs(docs_value, half), show(f))


def show_docs(value, half):
    return show(value)


def check_table(md, marker_line, marker, table_lines, root, cache, problems):
    rows, columns = read_rows(root, marker["file"], cache)
    specs = marker["columns"]
    for spec in specs:
        for ref in spec or []:
            if not ref["skip"]:
                if ref["name"] not in columns:
                    raise Problem(f"{marker['file']} has no column '{ref['name']}'")
                for c, _ in ref["cond"]:
                    if c not in columns:
                        raise Problem(f"{marker['file']} has no column '{c}'")
    for c, _ in marker["where"]:
        if c not in columns:
            raise Problem(f"{marker['file']} has no column '{c}'")
    pool = select(rows, marker["where"])
    (head_no, head), body = table_lines[0], table_lines[2:]
    names = split_row(head)
    if len(names) != len(specs):
        raise Problem(f"the table has {len(names)} columns, the marker's columns= {len(specs)}")
    key_index = []
    for k in marker["key"]:
        idx = [i for i, s in enumerate(specs)
               if s and not s[0]["skip"] and s[0]["name"] == k and not s[0]["cond"]]
        if not idx:
            raise Problem(f"key column '{k}' does not begin an entry of columns=")
        key_index.append(idx[0])
    if not marker["key"] and len(body) != len(pool):
        problems.append(f"{md}:{marker_line}: the table has {len(body)} rows, "
                        f"{marker['file']} has {len(pool)} (after where)")
    for n, (line_no, line) in enumerate(body):
        cells = split_row(line)
        if len(cells) != len(specs):
            problems.append(f"{md}:{line_no}: the row has {len(cells)} cells, the table {len(specs)}")
            continue
        key_text = ", ".join(f"{marker['key'][j]} {plain(cells[i])}" for j, i in enumerate(key_index))
        row_label = key_text or f"{n + 1}"

        def candidates(extra):
            cand = select(pool, extra)
            for j, i in enumerate(key_index):
                nums = parse_numbers(plain(cells[i]))[:1]  # a key is the cell's first value
                name = marker["key"][j]
                if len(nums) == 1:
                    # A key is equal to the file's value; if none is, rounded to it.
                    v, h = nums[0]
                    exact = [r for r in cand if to_float(r.get(name)) == v]
                    cand = exact or [r for r in cand if to_float(r.get(name)) is not None
                                     and agrees(v, h, to_float(r.get(name)))]
                else:
                    cand = [r for r in cand if plain(cells[i]) == (r.get(name) or "").strip()]
            return cand

        def row_for(ref, n=n):
            if marker["key"]:
                cand = candidates(ref["cond"])
                if len(cand) != 1:
                    raise Problem(f"{'no' if not cand else len(cand)} rows of {marker['file']} "
                                  f"match row {row_label}"
                                  + (f" with {ref['cond']}" if ref["cond"] else ""))
                return cand[0]
            if ref["cond"]:
                cand = select(pool, ref["cond"])
                if n >= len(cand):
                    raise Problem(f"row {row_label}: {marker['file']} has too few rows with {ref['cond']}")
                return cand[n]
            if n >= len(pool):
                raise Problem(f"row {row_label}: {marker['file']} has too few rows")
            return pool[n]

        def report(column, docs, file_value, line_no=line_no, row_label=row_label):
            problems.append(f"{md}:{line_no}: column {column}, row {row_label}: "
                            f"docs say {docs}, CSV says {file_value}")

        for i, (cell, spec) in enumerate(zip(cells, specs)):
            if spec is None:
                continue
            if i in key_index:  # its first value selected the row; check the rest
                if len(spec) == 1:
                    continue
                spec = [{"skip": True, "optional": False}] + spec[1:]
            try:
                check_cell(cell, spec, row_for, report, names[i])
            except Problem as e:
                problems.append(f"{md}:{line_no}: {e}")
                break


def check_value(md, marker_line, marker, paragraph, root, cache, problems):
    rows, columns = read_rows(root, marker["file"], cache)
    # A column named whole (a JSON key with spaces, `samples.mu0=0.5 seed=1.phi_0`,
    # quoted in the marker), else a SPEC of one column.
    ref = ([{"skip": False, "name": marker["column"], "cond": [], "factor": None, "optional": False}]
           if marker["column"] in columns
           else parse_spec(marker["column"]))
    if not ref or len(ref) != 1 or ref[0]["skip"]:
        raise Problem(f"column= must name one column, not '{marker['column']}'")
    ref = ref[0]
    for c in [ref["name"]] + [c for c, _ in marker["where"]]:
        if c not in columns:
            raise Problem(f"{marker['file']} has no column '{c}'")
    cand = select(rows, marker["where"])
    if len(cand) != 1:
        raise Problem(f"where= selects {len(cand)} rows of {marker['file']}, not one")
    value = cand[0].get(ref["name"], "")
    says = marker["says"]
    label = ", ".join(f"{c}={v}" for c, v in marker["where"]) or "1"
    # The paragraph's own words: the text of markers stacked below this one
    # holds their `says` too and must not answer for it.
    if says not in " ".join(MARKER.sub(" ", paragraph).split()):
        problems.append(f"{md}:{marker_line}: the paragraph below the marker does not say '{says}'")
    numbers = parse_numbers(says)
    f = to_float(value)
    if len(numbers) == 1 and f is not None and NUMBER.fullmatch(says.strip()):
        if ref["factor"] is not None:
            f *= ref["factor"]
        if not agrees(numbers[0][0], numbers[0][1], f):
            problems.append(f"{md}:{marker_line}: column {ref['name']}, row {label}: "
                            f"docs say {says}, CSV says {show(f)}")
    elif says not in value:
        problems.append(f"{md}:{marker_line}: column {ref['name']}, row {label}: "
                        f"docs say {says}, CSV says {value or '(empty)'}")


def check_file(md, root, cache, problems, listing=None):
    text = (root / md).read_text()
    lines = text.split("\n")
    offsets, pos = [], 0
    for line in lines:
        offsets.append(pos)
        pos += len(line) + 1
    guarded = 0
    for m in MARKER.finditer(text):
        start = text.count("\n", 0, m.start()) + 1
        end = text.count("\n", 0, m.end()) + 1
        kind = m.group(1)
        try:
            marker = parse_marker(kind, m.group(2))
            i = end  # 0-based index of the line after the marker's last line
            while i < len(lines) and lines[i].strip() == "":
                i += 1
            if kind == "table-source":
                if not (i + 1 < len(lines) and TABLE_ROW.match(lines[i]) and SEPARATOR.match(lines[i + 1])):
                    raise Problem("no table follows the table-source marker")
                j = i
                while j < len(lines) and TABLE_ROW.match(lines[j]):
                    j += 1
                table = [(k + 1, lines[k]) for k in range(i, j)]
                check_table(md, start, marker, table, root, cache, problems)
                if listing is not None:
                    listing.append(f"{md}:{i + 1}: table of {j - i - 2} rows from {marker['file']}")
            else:
                j = i
                while j < len(lines) and lines[j].strip() != "":
                    j += 1
                check_value(md, start, marker, "\n".join(lines[i:j]), root, cache, problems)
                if listing is not None:
                    listing.append(f"{md}:{start}: '{marker['says']}' from {marker['file']}")
            guarded += 1
        except Problem as e:
            problems.append(f"{md}:{start}: {e}")
    return guarded


def run(root, dirs, listing=None):
    problems, cache, guarded = [], {}, 0
    for d in dirs:
        for md in sorted((root / d).glob("*.md")):
            guarded += check_file(md.relative_to(root).as_posix(), root, cache, problems, listing)
    return problems, guarded


# ---------------------------------------------------------------- self-test

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
        if problems or guarded != 5:
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
