"""A marker's arguments, and the cells of the table below it."""
import re
import shlex

from . import Problem
from .numerals import DASHES
from .sources import parse_conditions

# A marker starts a line: an indented one is an example inside a code block.
MARKER = re.compile(r"^<!--\s*(table-source|value-source):(.*?)-->", re.S | re.M)
TABLE_ROW = re.compile(r"^\s*\|.*\|\s*$")
SEPARATOR = re.compile(r"^\s*\|[\s:|-]+\|\s*$")

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


# What a value-source marker with aggregate= says of the rows its where=s
# select: how many there are, or the least or greatest value of its column.
AGGREGATES = ("count", "min", "max")


def parse_marker(kind, body):
    try:
        words = shlex.split(body.replace("\n", " "))
    except ValueError as e:
        raise Problem(f"cannot read the marker: {e}")
    if not words:
        raise Problem("the marker names no file")
    marker = {"kind": kind, "file": words[0], "where": [], "key": [], "columns": None,
              "column": None, "says": None, "aggregate": None}
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
        elif opt == "aggregate":
            if val not in AGGREGATES:
                raise Problem(f"aggregate={val}: not one of {', '.join(AGGREGATES)}")
            marker["aggregate"] = val
        else:
            raise Problem(f"unknown option '{opt}' in the marker")
    if kind == "table-source" and marker["columns"] is None:
        raise Problem("a table-source marker needs columns=")
    if kind == "value-source" and marker["says"] is None:
        raise Problem("a value-source marker needs says=")
    if kind == "value-source" and marker["column"] is None and marker["aggregate"] != "count":
        raise Problem("a value-source marker needs column= (or aggregate=count)")
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
