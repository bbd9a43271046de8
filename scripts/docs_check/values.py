"""A number in prose against the file its marker names."""
from . import Problem
from .markers import MARKER, parse_spec
from .numerals import NUMBER, agrees, parse_numbers, show, to_float
from .sources import read_rows, select


def marker_column(marker, columns):
    """The one column a value-source marker names: named whole (a JSON key
    with spaces, `samples.mu0=0.5 seed=1.phi_0`, quoted in the marker), else a
    SPEC of one column (`frac*100`)."""
    ref = ([{"skip": False, "name": marker["column"], "cond": [], "factor": None, "optional": False}]
           if marker["column"] in columns
           else parse_spec(marker["column"]))
    if not ref or len(ref) != 1 or ref[0]["skip"]:
        raise Problem(f"column= must name one column, not '{marker['column']}'")
    if ref[0]["name"] not in columns:
        raise Problem(f"{marker['file']} has no column '{ref[0]['name']}'")
    return ref[0]


def selected_value(marker, rows, ref):
    """The file's value the marker speaks of, as text: its one selected row's
    value, or the count, least or greatest over the selected rows."""
    cand = select(rows, marker["where"])
    how = marker["aggregate"]
    if how is None:
        if len(cand) != 1:
            raise Problem(f"where= selects {len(cand)} rows of {marker['file']}, not one")
        return cand[0].get(ref["name"], "")
    if how == "count":
        return str(len(cand))
    if not cand:
        raise Problem(f"where= selects no row of {marker['file']} to take the {how} of")
    values = [to_float(r.get(ref["name"])) for r in cand]
    if None in values:
        raise Problem(f"aggregate={how}: column '{ref['name']}' holds a value that is not a number")
    return show((min if how == "min" else max)(values))


def check_value(md, marker_line, marker, paragraph, root, cache, problems):
    rows, columns = read_rows(root, marker["file"], cache)
    for c, _, _ in marker["where"]:
        if c not in columns:
            raise Problem(f"{marker['file']} has no column '{c}'")
    ref = (marker_column(marker, columns) if marker["column"] is not None
           else {"name": "(rows)", "factor": None})
    value = selected_value(marker, rows, ref)
    says = marker["says"]
    label = ", ".join(f"{c}{op}{v}" for c, op, v in marker["where"]) or "1"
    how = marker["aggregate"]
    what = (f"column {ref['name']}, row {label}" if how is None
            else f"count of the rows {label}" if how == "count"
            else f"{how} of column {ref['name']} over the rows {label}")
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
            problems.append(f"{md}:{marker_line}: {what}: docs say {says}, CSV says {show(f)}")
    elif says not in value:
        problems.append(f"{md}:{marker_line}: {what}: docs say {says}, CSV says {value or '(empty)'}")
