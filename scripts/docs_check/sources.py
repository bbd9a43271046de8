"""A marker's file as rows, and the conditions (`where=`, `[..]`) that select rows."""
import csv
import json
import re

from . import Problem
from .numerals import to_float


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


# COL=VALUE, COL!=VALUE, or a comparison of numbers: COL<VALUE, COL<=VALUE,
# COL>VALUE, COL>=VALUE. The first operator splits: a value may hold `=`
# (`point=000-seed=1_lambda=0.1`).
CONDITION = re.compile(r"^(?P<col>[^<>=!]+)(?P<op><=|>=|!=|<|>|=)(?P<val>.*)$")
COMPARISONS = {"<": lambda a, b: a < b, "<=": lambda a, b: a <= b,
               ">": lambda a, b: a > b, ">=": lambda a, b: a >= b}


def parse_conditions(text):
    """`where=` and `[..]` text as (column, operator, value) triples."""
    conds = []
    for part in text.split(","):
        m = CONDITION.match(part.strip())
        if not m:
            raise Problem(f"cannot read the condition '{part}' (COL=VALUE, COL<VALUE, ...)")
        op, val = m.group("op"), m.group("val").strip()
        if op in COMPARISONS and to_float(val) is None:
            raise Problem(f"the condition '{part}' compares with '{val}', not a number")
        conds.append((m.group("col").strip(), op, val))
    return conds


def holds(cond, row):
    col, op, val = cond
    file_value = row.get(col, "")
    if op == "=":
        return value_matches(val, file_value)
    if op == "!=":
        return not value_matches(val, file_value)
    f = to_float(file_value)
    return f is not None and COMPARISONS[op](f, to_float(val))


def select(rows, conds):
    return [r for r in rows if all(holds(c, r) for c in conds)]
