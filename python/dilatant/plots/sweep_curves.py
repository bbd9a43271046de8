"""The flow curves of a sweep's folder as the figures of dilatant.plots.sweep
draw them: its finished points grouped by phi and sample (a refinement's with
the points of the ramps it refines, docs/sweeps.md "Refining a ramp"), each
curve with its regime from DIR/analysis/curves.csv when present. Imported, not run.
"""
import math

if __package__:
    from .pressure_sweep import is_pressure
    from .table_rows import number, read_rows, refined_ramp_rows
else:  # beside sweep.py run as a script
    from pressure_sweep import is_pressure  # noqa
    from table_rows import number, read_rows, refined_ramp_rows  # noqa


class Curve:
    """The finished points of one flow curve (one phi and sample), by stress."""

    def __init__(self, phi, sample, rows):
        self.phi = phi
        self.sample = sample
        self.rows = sorted(rows, key=lambda r: number(r["lambda"]))
        self.mu0 = number(self.rows[0]["mu0"])
        self.regime = ""
        self.n = math.nan
        self.bagnold = ""
        # dilatant analyze's rule 8: where frac_bl starts to rise for good (NaN: none)
        self.contact_onset_rate = math.nan

    def flowing(self):
        return [r for r in self.rows if r["jammed"] != "true"]

    def label(self):
        text = f"$\\mu_0$ = {self.mu0:g}"
        extra = " ".join(self.sample.split(" ")[1:])  # beyond "mu0=..."
        if extra:
            text += f" ({extra})"
        text += f", $\\phi$ = {self.phi:g}"
        if self.regime:
            text += f": {self.regime}"
            if self.regime == "cst" and math.isfinite(self.n):
                text += f", n = {self.n:.2f}"
                if self.bagnold == "true":
                    text += " (Bagnold)"
        return text


def load_curves(out):
    rows = [r for r in read_rows(out / "flowcurves.csv") if r["status"] == "done"]
    merged = refined_ramp_rows(out, rows)  # a refinement's curves with their ramps' points
    refinement, rows = merged is not rows, merged
    groups = {}
    for r in rows:
        if is_pressure(r):  # phi measured, not fixed: mu(J), phi(J) instead
            continue
        groups.setdefault((number(r["phi"]), r["sample"]), []).append(r)
    curves = [Curve(phi, sample, rs) for (phi, sample), rs in groups.items()]
    curves.sort(key=lambda c: (c.mu0, c.sample, c.phi))
    analysis = out / "analysis" / "curves.csv"
    # A refinement's own analysis saw its extra points only, not the merged
    # curves: its regimes are not theirs, and the figures go unlabelled.
    if analysis.exists() and not refinement:
        for a in read_rows(analysis):
            for c in curves:
                if c.sample == a["sample"] and c.phi == number(a["phi"]):
                    c.regime, c.n, c.bagnold = a["regime"], number(a["n"]), a.get("bagnold", "")
                    c.contact_onset_rate = number(a.get("contact_onset_rate"))
    return rows, curves
