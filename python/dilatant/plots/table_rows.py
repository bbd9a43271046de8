"""The rows of a result table (a CSV file with a header: flowcurves.csv,
curves.csv, ...) as dicts of text, and the numbers in them: what the figures and
the tables of dilatant.plots read. Standard library only, so that the tables
(paper_tables, onset_table, ...) need no matplotlib. Imported, not run.
"""
import csv
import math
from pathlib import Path


def read_rows(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def number(text):
    """A cell as a float; NaN where it is empty, missing (None) or not a number."""
    try:
        return float(text)
    except (TypeError, ValueError):
        return math.nan


def refined_ramp_rows(folder, rows):
    """A refinement's rows (sweep.refines, docs/sweeps.md "Refining a ramp") with
    the finished points of the ramps it refines: one curve of both tables. Each
    extra point joins the curve of the ramp point its segment started from
    (followed through the `start` column), and takes that curve's phi and
    sample, which its own table may label differently (other swept keys); a
    ramp row's dir becomes absolute (the figures read its files). Rows of a
    sweep that refines nothing come back as they are."""
    try:
        import tomllib  # Python >= 3.11; before it no sweep is read as a refinement
        with open(Path(folder) / "sweep.toml", "rb") as f:
            refines = tomllib.load(f).get("sweep", {}).get("refines")
    except (ImportError, OSError, ValueError):
        return rows
    if not refines or not (Path(refines) / "flowcurves.csv").exists():
        return rows
    ramp_rows = [r for r in read_rows(Path(refines) / "flowcurves.csv") if r["status"] == "done"]
    by_dir = {(Path(refines) / r["dir"]).resolve(): r for r in ramp_rows}
    own = {r["dir"]: r for r in rows}
    curves, out = set(), []
    for r in rows:
        start = r.get("start", "")
        for _ in range(len(own)):  # along the segment, down to the ramp's point
            if start not in own:
                break
            start = own[start].get("start", "")
        ramp_point = by_dir.get((Path(folder) / start).resolve())
        if ramp_point is not None:
            r = dict(r, phi=ramp_point["phi"], sample=ramp_point["sample"])
            curves.add((r["phi"], r["sample"]))
        out.append(r)
    return out + [dict(r, dir=str(Path(refines) / r["dir"])) for r in ramp_rows
                  if (r["phi"], r["sample"]) in curves]
