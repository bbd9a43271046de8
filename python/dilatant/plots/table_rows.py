"""The rows of a result table (a CSV file with a header: flowcurves.csv,
curves.csv, ...) as dicts of text, and the numbers in them: what the figures and
the tables of dilatant.plots read. Standard library only, so that the tables
(paper_tables, onset_table, ...) need no matplotlib. Imported, not run.
"""
import csv
import math
import tomllib
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
    the finished points of the ramps it refines, those of its own curves (same
    phi and sample): one curve of both tables. A ramp row's dir becomes absolute
    (the figures read its files). Other sweeps' rows come back as they are."""
    try:
        with open(Path(folder) / "sweep.toml", "rb") as f:
            refines = tomllib.load(f).get("sweep", {}).get("refines")
    except (OSError, tomllib.TOMLDecodeError):
        return rows
    if not refines or not (Path(refines) / "flowcurves.csv").exists():
        return rows
    curves = {(r["phi"], r["sample"]) for r in rows}
    ramp = [dict(r, dir=str(Path(refines) / r["dir"]))
            for r in read_rows(Path(refines) / "flowcurves.csv")
            if r["status"] == "done" and (r["phi"], r["sample"]) in curves]
    return rows + ramp
