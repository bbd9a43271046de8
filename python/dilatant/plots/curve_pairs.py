"""Two flow curves point by point: how far apart each pair of points lies in
units of their combined standard error, and whether the pairs scatter as much
as their error bars say. What decides whether a rerun repeats a run, or two
seeds' curves agree (docs/paper-reproduction.md "The decisive study"):

    PYTHONPATH=python python3 -m dilatant.plots.curve_pairs A.csv B.csv --out PREFIX
        [--a-where COLUMN=VALUE ...] [--b-where COLUMN=VALUE ...]
        [--key lambda] [--quantity eta] [--blocks 10]

Reads the `done` rows of two flowcurves.csv tables (the same file twice for
two seeds of one sweep) that match their --a-where / --b-where filters (a
value compared as a number where both sides are numbers: lambda=1 matches
1.0; COLUMN<VALUE and COLUMN>VALUE keep the rows whose number lies below or
above, e.g. lambda<316 for a curve's stresses below tau 1e5), and pairs them
by --key. Writes PREFIX.csv, one row a pair in the order
of the key (its first column named after it):

    lambda, a, a_err, b, b_err, b_over_a, z, nu, z_normal, counted, reason

z = (b - a) / sqrt(a_err^2 + b_err^2). Each error bar is itself an estimate:
the engine's is the standard error of the means of 10 consecutive blocks of
the steady window (src/measure/flow_series.hpp), so z follows Student's t with
nu degrees of freedom (Welch–Satterthwaite, 9 a side, at most 18), not a
normal law: honest error bars give E[z^2] = nu / (nu - 2), 1.29 at nu 9.
z_normal is the normal deviate with z's two-sided t tail (--blocks N: N block
means behind each error bar, default 10; 0 takes the error bars as exact).
A pair is counted when both points are valid and steady and have a finite
value and a combined error above zero; otherwise `reason` says which side
failed what, and nu and z_normal are empty. And PREFIX.json:

    pairs, counted, chi2, chi2_raw, p_value, scale, mean_z, mean_z_err, ...

over the counted pairs: chi2 = sum z_normal^2 (chi2_raw = sum z^2, which
reads the error bars as exact). Two curves that differ only by the noise
their error bars measure give chi2 about `counted` (its p_value, the chance
of a larger chi2 by noise alone, is then not small); scale =
sqrt(chi2 / counted) is the factor the error bars would have to grow by to
explain the scatter; mean_z (of z_normal) a shift of one curve against the
other, whose standard error by noise alone is mean_z_err = 1 / sqrt(counted).
The pairs of independent runs are independent (chi^2 with `counted` degrees of
freedom); points of one ramp share its history, which this does not model.

Bad use (a file or column missing, a filter that matches nothing, a key twice
on one side, no key in common) exits 2 with one line. From Python,
`compare(a, b, a_where=["cell.seed=1"], ...)` returns the pairs and the
summary without writing files. Standard library only.
"""
import argparse
import json
import math
import os
import sys
from pathlib import Path
from statistics import NormalDist

from .table_rows import number, read_rows


class BadInput(ValueError):
    """A problem with the tables or the command line: one line, exit 2."""


def chi2_sf(x, k):
    """P(chi^2_k > x) for k >= 1 degrees of freedom, by the closed forms of the
    regularised upper incomplete gamma function Q(k/2, x/2) at integer and
    half-integer order (Abramowitz & Stegun 26.4.4 and 26.4.5)."""
    if x <= 0:
        return 1.0
    half = x / 2
    if k % 2 == 0:  # Q(n, h) = e^-h sum_{i<n} h^i / i!
        term = total = math.exp(-half)
        for i in range(1, k // 2):
            term *= half / i
            total += term
        return min(total, 1.0)
    # Q(n + 1/2, h) = erfc(sqrt h) + e^-h sum_{i=1..n} h^(i-1/2) / Gamma(i + 1/2)
    total = math.erfc(math.sqrt(half))
    term = math.exp(-half) * math.sqrt(half) / math.gamma(1.5)
    for i in range(1, (k - 1) // 2 + 1):
        total += term
        term *= half / (i + 0.5)
    return min(total, 1.0)


def t_two_sided(t, nu):
    """P(|T_nu| > |t|) for Student's t with integer nu >= 1 degrees of freedom
    (Abramowitz & Stegun 26.7.3 and 26.7.4, in theta = atan(|t| / sqrt(nu)))."""
    theta = math.atan(abs(t) / math.sqrt(nu))
    c2 = math.cos(theta) ** 2
    if nu % 2 == 1:  # A = 2/pi [theta + sin cos (1 + 2/3 cos^2 + (2*4)/(3*5) cos^4 + ...)]
        series, term = 0.0, 1.0
        for j in range(1, (nu - 1) // 2 + 1):
            series += term
            term *= c2 * (2 * j) / (2 * j + 1)
        inside = theta + math.sin(theta) * math.cos(theta) * series
        return max(0.0, 1.0 - 2.0 / math.pi * inside)
    series, term = 0.0, 1.0  # A = sin (1 + 1/2 cos^2 + (1*3)/(2*4) cos^4 + ...)
    for j in range(1, nu // 2 + 1):
        series += term
        term *= c2 * (2 * j - 1) / (2 * j)
    return max(0.0, 1.0 - math.sin(theta) * series)


def normal_equivalent(z, nu):
    """The standard normal deviate with the two-sided tail of z under Student's
    t with nu degrees of freedom: what z means when its error bar is itself
    estimated from nu + 1 blocks. Tails below 1e-15 (|z'| about 8) are held there:
    such a pair disagrees by any measure, and 1 - A has no digits left."""
    p = max(t_two_sided(z, nu), 1e-15)
    return math.copysign(-NormalDist().inv_cdf(p / 2), z)


def welch_nu(a_err, b_err, blocks):
    """The combined error's degrees of freedom (Welch–Satterthwaite), each side's
    error a standard error of `blocks` block means (blocks - 1 each), rounded
    down: fewer degrees, heavier tails, a smaller z'."""
    each = blocks - 1
    nu = (a_err**2 + b_err**2) ** 2 / (a_err**4 / each + b_err**4 / each)
    return max(1, math.floor(nu + 1e-9))


OPERATORS = "=<>"


def parse_where(items, flag):
    """COLUMN=VALUE, COLUMN<VALUE or COLUMN>VALUE, each as (column, operator, value)."""
    out = []
    for item in items:
        at = min((item.find(op) for op in OPERATORS if op in item), default=-1)
        column, op, value = item[:at], item[at:at + 1], item[at + 1:]
        if at <= 0:
            raise BadInput(f"{flag} {item!r}: expected COLUMN=VALUE, COLUMN<VALUE or COLUMN>VALUE")
        if op != "=" and not math.isfinite(number(value)):
            raise BadInput(f"{flag} {item!r}: {op} compares numbers, and {value!r} is none")
        out.append((column, op, value))
    return out


def same(text, value):
    a, b = number(text), number(value)
    if math.isfinite(a) and math.isfinite(b):
        return math.isclose(a, b, rel_tol=1e-9, abs_tol=0.0)
    return text == value


def matches(text, op, value):
    """Whether a row's field passes one filter (a field that is no number
    passes no < or > filter)."""
    if op == "=":
        return same(text, value)
    a = number(text)
    return math.isfinite(a) and (a < number(value) if op == "<" else a > number(value))


def side(path, where, key, quantity, name):
    """The `done` rows of one table that match its filters, by key value."""
    path = Path(path)
    if not path.is_file():
        raise BadInput(f"{path}: no such file")
    rows = read_rows(path)
    columns = set(rows[0]) if rows else set()
    needed = {"status", "valid", "steady", key, quantity, quantity + "_err"}
    needed |= {column for column, _, _ in where}
    missing = sorted(needed - columns)
    if missing:
        raise BadInput(f"{path}: no column {', '.join(missing)}")
    chosen = {}
    for line, r in enumerate(rows, start=2):
        if r["status"] != "done" or not all(matches(r[c], op, v) for c, op, v in where):
            continue
        k = number(r[key])
        if not math.isfinite(k):
            raise BadInput(f"{path}:{line}: {key} {r[key]!r} is not a number")
        if any(math.isclose(k, seen, rel_tol=1e-9) for seen in chosen):
            raise BadInput(f"{path}:{line}: {key} {r[key]} a second time among the rows of "
                           f"{name} (narrow them with --{name}-where)")
        chosen[k] = r
    if not chosen:
        raise BadInput(f"{path}: no finished row matches --{name}-where "
                       f"{' '.join(f'{c}{op}{v}' for c, op, v in where) or '(none)'}")
    return chosen


def why_not_counted(r, quantity, name):
    if r["valid"] != "true":
        return f"{name} invalid"
    if r["steady"] != "true":
        return f"{name} not steady"
    if not math.isfinite(number(r[quantity])) or not math.isfinite(number(r[quantity + "_err"])):
        return f"{name} has no {quantity}"
    return ""


def pairs(a_rows, b_rows, quantity, blocks):
    keys = sorted(k for k in a_rows if any(math.isclose(k, kb, rel_tol=1e-9) for kb in b_rows))
    out = []
    for k in keys:
        ra = a_rows[k]
        rb = next(r for kb, r in b_rows.items() if math.isclose(k, kb, rel_tol=1e-9))
        a, a_err = number(ra[quantity]), number(ra[quantity + "_err"])
        b, b_err = number(rb[quantity]), number(rb[quantity + "_err"])
        reason = why_not_counted(ra, quantity, "a") or why_not_counted(rb, quantity, "b")
        combined = math.hypot(a_err, b_err)
        z = (b - a) / combined if combined > 0 else math.nan
        if not reason and not combined > 0:
            reason = "no error bar on either side"
        nu = welch_nu(a_err, b_err, blocks) if blocks and not reason else None
        z_normal = math.nan if reason else normal_equivalent(z, nu) if nu else z
        out.append({"key": k, "a": a, "a_err": a_err, "b": b, "b_err": b_err,
                    "b_over_a": b / a if a else math.nan, "z": z, "nu": nu if nu else "",
                    "z_normal": z_normal, "counted": not reason, "reason": reason})
    return out


def summary(rows):
    z = [r["z_normal"] for r in rows if r["counted"]]
    n = len(z)
    chi2 = sum(v * v for v in z)
    chi2_raw = sum(r["z"] ** 2 for r in rows if r["counted"])
    return {"pairs": len(rows), "counted": n,
            "chi2": chi2 if n else None,
            "chi2_raw": chi2_raw if n else None,
            "p_value": chi2_sf(chi2, n) if n else None,
            "scale": math.sqrt(chi2 / n) if n else None,
            "mean_z": sum(z) / n if n else None,
            "mean_z_err": 1 / math.sqrt(n) if n else None}


def write_atomic(path, text):
    part = Path(str(path) + ".part")
    part.write_text(text)
    os.replace(part, path)


def cell(value):
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, float):
        return "" if not math.isfinite(value) else repr(value)
    return str(value)


def compare(a, b, a_where=(), b_where=(), key="lambda", quantity="eta", blocks=10):
    """From Python: the pairs (a list of dicts, the CSV's columns, `key` under
    "key") and the summary (the JSON's numbers) of two flowcurves.csv files,
    filtered by COLUMN=VALUE (or <, >) strings. Raises BadInput (a ValueError) with the
    line the command line prints."""
    if blocks < 0 or blocks == 1:
        raise BadInput(f"--blocks {blocks}: an error bar needs at least 2 blocks (0: exact)")
    a_filters, b_filters = parse_where(a_where, "--a-where"), parse_where(b_where, "--b-where")
    a_rows = side(a, a_filters, key, quantity, "a")
    b_rows = side(b, b_filters, key, quantity, "b")
    rows = pairs(a_rows, b_rows, quantity, blocks)
    if not rows:
        raise BadInput(f"{a} and {b}: no {key} in common among the chosen rows")
    return rows, summary(rows)


def main(argv):
    parser = argparse.ArgumentParser(prog="python3 -m dilatant.plots.curve_pairs",
                                     description="Two flow curves point by point.")
    parser.add_argument("a")
    parser.add_argument("b")
    parser.add_argument("--out", required=True, help="PREFIX of PREFIX.csv and PREFIX.json")
    parser.add_argument("--a-where", action="append", default=[], metavar="COLUMN=VALUE",
                        help="keep a's rows where COLUMN=VALUE (or COLUMN<VALUE, COLUMN>VALUE)")
    parser.add_argument("--b-where", action="append", default=[], metavar="COLUMN=VALUE",
                        help="keep b's rows where COLUMN=VALUE (or COLUMN<VALUE, COLUMN>VALUE)")
    parser.add_argument("--key", default="lambda")
    parser.add_argument("--quantity", default="eta")
    parser.add_argument("--blocks", type=int, default=10,
                        help="block means behind each error bar (0: error bars exact)")
    args = parser.parse_args(argv)  # argparse's own errors exit 2 too
    try:
        rows, result = compare(args.a, args.b, args.a_where, args.b_where, args.key,
                               args.quantity, args.blocks)
    except BadInput as e:
        print(f"curve_pairs: {e}", file=sys.stderr)
        return 2
    fields = ["key", "a", "a_err", "b", "b_err", "b_over_a", "z", "nu", "z_normal", "counted",
              "reason"]
    lines = [",".join([args.key] + fields[1:])]
    lines += [",".join(cell(r[f]) for f in fields) for r in rows]
    write_atomic(Path(args.out + ".csv"), "\n".join(lines) + "\n")
    result.update({"a": args.a, "a_where": args.a_where, "b": args.b, "b_where": args.b_where,
                   "key": args.key, "quantity": args.quantity, "blocks": args.blocks})
    write_atomic(Path(args.out + ".json"), json.dumps(result, indent=2) + "\n")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
