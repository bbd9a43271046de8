"""The rows of a result table (a CSV file with a header: flowcurves.csv,
curves.csv, ...) as dicts of text, and the numbers in them: what the figures and
the tables of dilatant.plots read. Standard library only, so that the tables
(paper_tables, onset_table, ...) need no matplotlib. Imported, not run.
"""
import csv
import math


def read_rows(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def number(text):
    """A cell as a float; NaN where it is empty, missing (None) or not a number."""
    try:
        return float(text)
    except (TypeError, ValueError):
        return math.nan
