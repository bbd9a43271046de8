"""The CSV files of a run as numpy structured arrays, one field per column:
integers where every value is one, floats (NaN for an empty cell) where every
value is a number, strings otherwise. Numbers are parsed exactly (Python's
float() rounds correctly), so the arrays hold the files' values bit for bit.
"""
import csv
import io
import math
from pathlib import Path


def _column(values):
    import numpy as np  # here, not at import: `import dilatant` works without numpy

    if all(v == "" for v in values):
        return np.array(values, dtype=str)
    try:
        return np.array([int(v) for v in values], dtype=np.int64)
    except ValueError:
        pass
    try:
        return np.array([float(v) if v != "" else math.nan for v in values], dtype=np.float64)
    except ValueError:
        return np.array(values, dtype=str)


def read_table(source):
    """A CSV file (path) or CSV text (a str holding a newline) as a structured array."""
    if isinstance(source, str) and "\n" in source:
        text = source
    else:
        text = Path(source).read_text()
    import numpy as np

    rows = list(csv.reader(io.StringIO(text)))
    if not rows:
        return np.zeros(0)
    header, data = rows[0], [r for r in rows[1:] if r]
    columns = [_column([r[k] if k < len(r) else "" for r in data]) for k in range(len(header))]
    dtype = [(name, c.dtype if len(data) else np.float64) for name, c in zip(header, columns)]
    table = np.zeros(len(data), dtype=dtype)
    for name, c in zip(header, columns):
        if len(data):
            table[name] = c
    return table
