"""Markdown tables of the paper reproduction, from the sweep tables in docs/.

Usage: PYTHONPATH=python python3 -m dilatant.plots.paper_tables DOCS_DIR > DOCS_DIR/tables.md

DOCS_DIR holds one folder per sweep (fig2, coulomb, boundary, dst-checks), each with
the `flowcurves.csv` (and `curves.csv`, the regime per curve) that
scripts/docs-paper.sh copied from its sweep folder. Every number printed here
is read from those files; nothing is computed but tau = lambda^2 and sums of
run times. Points outside the model's validity are marked, never dropped.
"""
import math
import re
import sys
from pathlib import Path

from .table_rows import number, read_rows

SWEEPS = [
    ("fig2", "Fig. 2: flow curves for five mu0 at phi 0.58 and mu0 0.3 at phi 0.59"),
    ("coulomb", "Control: `coulomb` law (no hydrodynamics), phi 0.58, mu0 0.1"),
    ("boundary", "Denser cells: where does DST appear?"),
    ("dst-checks", "phi 0.58, mu0 0.4 at lambda 100: run length, time step, wall mass"),
    ("dense-window", "The literal model's dense window (15 x 10 x 18 cell, two seeds)"),
    ("newtonian-fluid", "Fluid forces (films + drag), phi 0.58, mu0 0.1 and 0.4 (15 x 10 x 18 cell)"),
    ("newtonian-films", "Squeeze films alone, phi 0.58 (15 x 10 x 18 cell; two points)"),
    ("fluid-checks", "Film regularisation and beyond_s_lim (15 x 10 x 18 cell)"),
    ("newtonian-phi", "Fluid forces: eta_N against phi at lambda 1 (15 x 10 x 18 cell)"),
]


def fmt(v, digits=3):
    if not math.isfinite(v):
        return ""
    return f"{v:.{digits}g}"


def with_error(row, key):
    v, e = number(row.get(key)), number(row.get(key + "_err"))
    if not math.isfinite(v):
        return ""
    return f"{fmt(v)} ± {fmt(e, 2)}" if math.isfinite(e) else fmt(v)


def point_state(row):
    if row.get("status") != "done":
        return row.get("status", "?") + (f": {row['error']}" if row.get("error") else "")
    if row.get("jammed") == "true":
        return "**jammed**"
    if row.get("valid") == "true":
        return "valid"
    reasons = []
    if number(row.get("frac_over_slim")) > 0.05:
        reasons.append("s > s_lim")
    if row.get("profile_consistent") == "false":
        reasons.append("profile")
    if row.get("steady") == "false":
        reasons.append("drifting")
    return "invalid (" + ", ".join(reasons or ["?"]) + ")"


def start_of(row):
    """cold, or "after lambda X" for a point continued from its predecessor."""
    m = re.search(r"lambda=([^_/]+)", row.get("start", ""))
    return f"after lambda {m.group(1)}" if m else row.get("start", "")


def points_table(rows):
    head = ("| phi | phi_bulk | seed | mu0 | lambda | tau | gamma_dot | eta | P_BL | beyond s_lim "
            "| gamma_dot_bulk / gap | I | start | strain | run time | state |")
    lines = [head, "|" + "---|" * 16]
    # One curve after the other, each in increasing stress.
    for r in sorted(rows, key=lambda r: (number(r.get("phi")), number(r.get("cell.seed", "1")),
                                         number(r.get("mu0")), number(r.get("lambda")))):
        lam = number(r.get("lambda"))
        bulk, gap = number(r.get("gamma_dot_bulk")), number(r.get("gamma_dot_gap"))
        ratio = fmt(bulk / gap, 2) if gap > 0 else ""
        lines.append("| " + " | ".join([
            r.get("phi", ""), fmt(number(r.get("phi_bulk"))), r.get("cell.seed", "1"),
            r.get("mu0", ""), fmt(lam), fmt(lam * lam),
            with_error(r, "gamma_dot"), with_error(r, "eta"), fmt(number(r.get("frac_bl")), 2),
            fmt(number(r.get("frac_over_slim")), 2), ratio,
            fmt(number(r.get("inertial_number")), 2),
            start_of(r), fmt(number(r.get("strain"))), fmt(number(r.get("wall_time_s")), 3) + " s",
            point_state(r)]) + " |")
    return lines


def curves_table(path):
    lines = ["| curve | phi | eta_N | onset stress | n (95% interval) | regime | Bagnold |",
             "|---|---|---|---|---|---|---|"]
    for c in read_rows(path):
        n = number(c.get("n"))
        interval = f"{fmt(n)} ({fmt(number(c['n_low']))}-{fmt(number(c['n_high']))})" \
            if math.isfinite(n) else ""
        lines.append("| " + " | ".join([
            c["sample"], c["phi"], fmt(number(c.get("eta_newtonian"))),
            fmt(number(c.get("onset_stress"))), interval,
            c["regime"] + (f" ({c['dst_evidence']})" if c.get("dst_evidence") else ""),
            c.get("bagnold", "")]) + " |")
    return lines


def main():
    if len(sys.argv) != 2:
        print(__doc__, file=sys.stderr)
        return 2
    docs = Path(sys.argv[1])
    out = ["# Paper reproduction: every point",
           "",
           "Written by `dilatant.plots.paper_tables` from the `flowcurves.csv` and",
           "`curves.csv` beside this file (`bash scripts/docs-paper.sh`). Paper units:",
           "gamma_dot in eta_f/(rho_p R^2), eta in eta_f, tau = lambda^2 in",
           "eta_f^2/(rho_p R^2). `start`: cold (new packing) or the lambda whose final",
           "state the point continues.",
           "Run time: wall-clock seconds of one point on one core.", ""]
    for name, title in SWEEPS:
        table = docs / name / "flowcurves.csv"
        if not table.exists():
            continue
        rows = read_rows(table)
        versions = sorted({r["version"] for r in rows if r.get("version")})
        times = [number(r.get("wall_time_s")) for r in rows]
        total = sum(t for t in times if math.isfinite(t))
        out += [f"## {title}", "",
                f"`{name}/flowcurves.csv`, settings in `{name}/sweep.toml`; dilatant "
                f"{', '.join(versions) or '?'}; {len(rows)} points, "
                f"{total / 3600:.2f} core-hours.", ""]
        out += points_table(rows) + [""]
        if (docs / name / "curves.csv").exists():
            out += ["Per curve (`dilatant analyze`'s classifier, docs/sweeps.md):", ""]
            out += curves_table(docs / name / "curves.csv") + [""]
    print("\n".join(out))
    return 0


if __name__ == "__main__":
    sys.exit(main())
