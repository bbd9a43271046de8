#!/usr/bin/python3
"""Figures of a sweep (`dilatant sweep`, `dilatant plot`), drawn from its folder.

Usage: python3 python/dilatant/plots/sweep.py DIR
   or: dilatant.plots.sweep.draw(DIR)

Reads DIR/flowcurves.csv, DIR/analysis/curves.csv (the regime of each curve,
when present) and, per point, DIR/points/*/sommerfeld_hist.csv and config.toml;
a refinement's (sweep.refines) curves include the points of the ramps it refines.
Writes PNG and SVG into DIR/plots/ (no fitting here: the numbers come from C++):

  flow_curves.*       eta vs gamma_dot, log-log, every curve of the sweep: colour
                      = the curve's sample (mu0 and the other swept keys), marker
                      = phi (the paper's Fig. 2);
  fig1b_viscosity.*   eta vs gamma_dot of one curve (mu0 = 0.1 when swept, else the
                      first), each point labelled with its shear stress (Fig. 1b);
  fig1c_sommerfeld.*  P(s) of the contacts at each stress of that curve, with the
                      friction law mu(s) drawn over it (Fig. 1c);
  fig1d_contacts.*    P_BL and P_HD = 1 - P_BL vs gamma_dot for that curve (Fig. 1d);
  mu_phi_of_J.*       under cell.control = "pressure": mu_eff and phi_bulk vs J
                      (pressure_sweep.py); those points are in no flow curve.

Every point outside the model's validity (valid: false) is drawn hollow and grey
and labelled so, never as a result; a jammed point (the wall stopped: gamma_dot 0,
eta infinite) is drawn as an upward arrow at the last flowing shear rate of its
curve. The caption of each figure states the version and the settings.

Needs Debian's python3-matplotlib and python3-numpy (and tomllib, Python >= 3.11);
exits with status 3 and one line on stderr when they are missing (the C++ command
then reports the plots as skipped), with status 4 when no point is finished.
Files are written to NAME.part and renamed, like every result file.
"""
import csv
import json
import math
import sys
from pathlib import Path

if __package__:
    from .common import RATE, VISCOSITY, NothingToPlot, exit_missing, number, read_rows, save
    from .pressure_sweep import mu_phi_figure
    from .sweep_curves import load_curves
else:  # a script (the CLI: python3 sweep.py DIR): common.py lies beside it, a folder
    # not on the path under python3 -P or PYTHONSAFEPATH. Without matplotlib it exits 3.
    sys.path.insert(0, str(Path(__file__).resolve().parent))
    from common import (RATE, VISCOSITY, NothingToPlot, exit_missing, number,  # noqa
                        read_rows, save)
    from pressure_sweep import mu_phi_figure  # noqa
    from sweep_curves import load_curves  # noqa

try:
    import tomllib
except ImportError as e:  # Python < 3.11
    exit_missing(e)

import matplotlib  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

STRESS_UNIT = r"$\eta_f^2/(\rho_p R^2)$"
MARKERS = ["o", "s", "^", "D", "v", "P", "X", "<", ">"]
INVALID = "0.6"  # grey of points outside the model's validity


def stress_text(v):
    """9, 900, 9e+04 -> "9", "900", "9\\times10^{4}" (math text)."""
    if not math.isfinite(v):
        return "?"
    if 1e-2 <= abs(v) < 1e4:
        return f"{v:.3g}"
    exponent = math.floor(math.log10(abs(v)))
    mantissa = v / 10 ** exponent
    head = "" if abs(mantissa - 1) < 5e-3 else f"{mantissa:.3g}\\times"
    return f"{head}10^{{{exponent}}}"


def analysis_version(out):
    """The version that wrote the sweep's analysis (analysis/fits.json), or None."""
    try:
        with open(out / "analysis" / "fits.json") as f:
            return json.load(f).get("version")
    except (OSError, ValueError):
        return None


def settings_caption(out, rows, swept):
    """One or two lines: version, cell, run and model settings of the sweep."""
    first = rows[0]
    try:
        with open(out / first["dir"] / "config.toml", "rb") as f:
            config = tomllib.load(f)
    except (OSError, tomllib.TOMLDecodeError):
        config = None
    # The runs' versions (several when a sweep was resumed by another one), and
    # the analysis's when it differs: the regimes drawn are the analysis's.
    versions = "+".join(sorted({r["version"] for r in rows if r.get("version")}))
    parts = [f"dilatant {versions or first['version']}"]
    analysed = analysis_version(out)
    if analysed and analysed != versions:
        parts[0] += f" (regimes: analysis by {analysed})"
    if config:
        size = "x".join(f"{v:g}" for v in config["cell"]["size"])
        parts.append(f"cell {size} R, {first['mobile_spheres']} mobile spheres")
        run = config["run"]
        parts.append(f"strain {run['strain']:g} (averaged after {run['transient_strain']:g})")
        fr = config["friction"]
        if fr["law"] == "critical_load":  # reads the load, not s (docs/model.md "Friction")
            parts.append(f"critical_load law, $F^*$ = {fr['critical_load']:g} "
                         r"$\eta_f^2/\rho_p$")
        else:
            parts.append(f"{fr['law']} law, $s_c$ = {fr['s_c']:g}, "
                         f"$s_{{lim}}$ = {fr['s_lim']:g}")
        parts.append(f"solver tolerance {config['solver']['tolerance']:g}")
    parts.append("swept: " + (", ".join(swept) if swept else "nothing"))
    text = "; ".join(parts)
    cut = text.find("; ", len(text) // 2)
    return text if cut < 0 else text[:cut + 1] + "\n" + text[cut + 2:]


VALIDITY_NOTE = ("hollow grey: outside the model's validity (valid: false; more than 5% of "
                 "contacts beyond $s_{lim}$, or no linear velocity profile), not a result")


def caption(fig, text):
    fig.text(0.01, -0.01, text, fontsize=6.5, ha="left", va="top", color="0.25")


def draw_jams(ax, curve, colour):
    """An upward arrow at the last flowing rate: above it the cell jams (DST)."""
    jammed = [r for r in curve.rows if r["jammed"] == "true"]
    flowing = curve.flowing()
    if not jammed or not flowing:
        return
    last = flowing[-1]
    x, y = number(last["gamma_dot"]), number(last["eta"])
    stress = number(jammed[0]["shear_stress"])
    ax.annotate("", xy=(x, y * 5), xytext=(x, y),
                arrowprops={"arrowstyle": "-|>", "color": colour, "lw": 1.2})
    ax.text(x * 1.08, y * 3, f"jams at $\\tau$ = ${stress_text(stress)}$", color=colour,
            fontsize=7, va="center")


def draw_curve(ax, curve, colour, marker, label):
    """Valid points filled and joined; invalid ones hollow grey; jams as an arrow."""
    flowing = curve.flowing()
    rate = np.array([number(r["gamma_dot"]) for r in flowing])
    eta = np.array([number(r["eta"]) for r in flowing])
    valid = np.array([r["valid"] == "true" for r in flowing], dtype=bool)
    err = np.array([number(r["eta_err"]) for r in flowing])
    ax.plot(rate, eta, "-", color=colour, lw=0.8, alpha=0.5)
    if valid.any():
        ax.errorbar(rate[valid], eta[valid], yerr=np.nan_to_num(err[valid]), fmt=marker, ms=5,
                    color=colour, capsize=2, lw=0.8, label=label)
    else:  # the curve's legend entry all the same: its colour and marker, hollow
        ax.plot([], [], marker, ls="-", lw=0.8, ms=5, mfc="none", color=colour, label=label)
    ax.plot(rate[~valid], eta[~valid], marker, ls="none", ms=5, mfc="none", mec=INVALID)
    draw_jams(ax, curve, colour)
    if not flowing:
        return f"{label}: jammed at every stress"
    return None


def log_axes(ax):
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel(RATE)
    ax.set_ylabel(VISCOSITY)


def bagnold_guide(ax, curves):
    """A dashed line of slope 1 (eta ∝ gamma_dot, Bagnold) for the eye."""
    pts = [(number(r["gamma_dot"]), number(r["eta"])) for c in curves for r in c.flowing()]
    pts = [(x, y) for x, y in pts if x > 0 and y > 0]
    if len(pts) < 2:
        return
    xs = np.array([p[0] for p in pts])
    ys = np.array([p[1] for p in pts])
    top = np.argmax(xs)
    g = np.geomspace(xs[top] / 10, xs[top], 10)
    ax.plot(g, ys[top] * 0.5 * g / xs[top], "--", color="0.4", lw=0.8,
            label=r"$\eta \propto \dot\gamma$ (Bagnold)")


def flow_curves_figure(out, rows, curves, swept):
    fig, ax = plt.subplots(figsize=(6.4, 4.8), constrained_layout=True)
    samples = sorted({c.sample for c in curves}, key=lambda s: [c.mu0 for c in curves
                                                                if c.sample == s][0])
    phis = sorted({c.phi for c in curves})
    cmap = matplotlib.colormaps["viridis"]
    notes = []
    for c in curves:
        k = samples.index(c.sample)
        colour = cmap(0.8 * k / max(len(samples) - 1, 1))  # the pale end reads badly
        marker = MARKERS[phis.index(c.phi) % len(MARKERS)]
        note = draw_curve(ax, c, colour, marker, c.label())
        if note:
            notes.append(note)
    bagnold_guide(ax, curves)
    if any(r["valid"] != "true" and r["jammed"] != "true" for r in rows):
        ax.plot([], [], "o", ls="none", mfc="none", mec=INVALID, label="outside validity")
    log_axes(ax)
    # The curves in their order (errorbar entries would come after plain lines), then guides.
    handles, labels = ax.get_legend_handles_labels()
    order = [c.label() for c in curves]
    ranked = sorted(zip(handles, labels),
                    key=lambda hl: order.index(hl[1]) if hl[1] in order else len(order))
    ax.legend(*zip(*ranked), fontsize=7, loc="best")
    ax.set_title("Viscosity vs shear rate per $\\mu_0$ and $\\phi$ (paper Fig. 2)", fontsize=10)
    caption(fig, settings_caption(out, rows, swept) + "\n" + VALIDITY_NOTE +
            "\narrow: the cell jams (the wall stops) at the stresses above its curve's last "
            "flowing point: DST" + ("\n" + "; ".join(notes) if notes else ""))
    save(fig, out / "plots", "flow_curves")


def chosen_curve(curves):
    """The curve of Fig. 1: mu0 0.1 (Stribeck), phi nearest 0.58; else the longest."""
    candidates = [c for c in curves if abs(c.mu0 - 0.1) < 1e-12 and "coulomb" not in c.sample]
    if candidates:
        return min(candidates, key=lambda c: (abs(c.phi - 0.58), c.sample))
    return max(curves, key=lambda c: len(c.rows))


def stress_colours(curve):
    cmap = matplotlib.colormaps["plasma"]
    n = len(curve.rows)
    return {r["dir"]: cmap(0.85 * k / max(n - 1, 1)) for k, r in enumerate(curve.rows)}


def fig1b(out, rows, curve, colours, swept):
    fig, ax = plt.subplots(figsize=(5.6, 4.4), constrained_layout=True)
    flowing = curve.flowing()
    ax.plot([number(r["gamma_dot"]) for r in flowing], [number(r["eta"]) for r in flowing], "-",
            color="0.5", lw=0.8)
    for r in flowing:
        x, y = number(r["gamma_dot"]), number(r["eta"])
        ok = r["valid"] == "true"
        if ok:
            ax.errorbar([x], [y], yerr=[np.nan_to_num(number(r["eta_err"]))], fmt="o", ms=7,
                        color=colours[r["dir"]], capsize=2)
        else:
            ax.plot([x], [y], "o", ms=7, color=INVALID, mfc="none")
        ax.annotate(f"$\\tau = {stress_text(number(r['shear_stress']))}$", (x, y),
                    textcoords="offset points", xytext=(6, -10), fontsize=7)
    draw_jams(ax, curve, "k")
    log_axes(ax)
    ax.set_title(f"{curve.label()} (paper Fig. 1b)\nstress $\\tau$ in {STRESS_UNIT}",
                 fontsize=9)
    caption(fig, settings_caption(out, rows, swept) + "\n" + VALIDITY_NOTE)
    save(fig, out / "plots", "fig1b_viscosity")


def friction_law(law, s, mu0, s_c, s_lim):
    """mu(s): the paper's Eq. 1 (stribeck, held at s_lim beyond), or mu0 (coulomb;
    critical_load, whose mu0 holds from the critical load on: it does not read s)."""
    if law in ("coulomb", "critical_load"):
        return np.full_like(s, mu0)
    hd = lambda x: 2 * np.pi * x * np.log(5 / (6 * np.pi * x))  # noqa: E731
    return np.where(s < s_c, mu0, np.where(s < s_lim, hd(np.minimum(s, s_lim)), hd(s_lim)))


def fig1c(out, rows, curve, colours, swept):
    fig, ax = plt.subplots(figsize=(6.0, 4.4), constrained_layout=True)
    lowest, highest = 1.0, 1.0
    for r in curve.rows:
        path = out / r["dir"] / "sommerfeld_hist.csv"
        if not path.exists():
            continue
        hist = read_rows(path)
        stick = number(hist[0]["fraction"])  # the first row: sticking contacts (s = 0)
        bins = [h for h in hist[2:] if h["s_high"] != "inf"]
        lo = np.array([number(h["s_low"]) for h in bins])
        hi = np.array([number(h["s_high"]) for h in bins])
        frac = np.array([number(h["fraction"]) for h in bins])
        density = frac / np.log10(hi / lo)  # per decade of s
        centre = np.sqrt(lo * hi)
        if (frac > 0).any():
            lowest = min(lowest, lo[frac > 0].min())
            highest = max(highest, hi[frac > 0].max())
        ok = r["valid"] == "true"
        # A distribution outside the model's validity: dotted and pale, and said so.
        ax.plot(centre, density, "-" if ok else ":", lw=1.4 if ok else 1.1,
                color=colours[r["dir"]], alpha=1.0 if ok else 0.6,
                label=f"$\\tau = {stress_text(number(r['shear_stress']))}$ "
                f"(stick {100 * stick:.1f}%)" + ("" if ok else ", outside validity"))
    mu0, s_c = curve.mu0, number(curve.rows[0]["s_c"])
    s_lim = 0.1
    try:
        with open(out / curve.rows[0]["dir"] / "config.toml", "rb") as f:
            s_lim = tomllib.load(f)["friction"]["s_lim"]
    except (OSError, KeyError, tomllib.TOMLDecodeError):
        pass
    ax.set_xscale("log")
    ax.set_xlim(max(lowest / 3, 1e-10), highest * 3)
    ax.set_xlabel(r"Sommerfeld number $s = \eta_f |v_t| R_p / N$")
    ax.set_ylabel(r"$P(s)$ per decade of $s$ (contacts that slide)")
    law = ax.twinx()
    s = np.geomspace(*ax.get_xlim(), 400)
    name = curve.rows[0]["friction_law"]
    law.plot(s, friction_law(name, s, mu0, s_c, s_lim), "k-", lw=1.5,
             label=f"friction law $\\mu(s)$ ({name})")
    law.set_ylabel(r"friction coefficient $\mu(s)$")
    law.set_ylim(0, max(0.7, mu0 * 1.3))
    for x, name in ((s_c, "$s_c$"), (s_lim, "$s_{lim}$")):
        ax.axvline(x, color="0.3", ls="--", lw=0.7)
        ax.text(x, 0.01, name + " ", transform=ax.get_xaxis_transform(), fontsize=8, ha="right",
                va="bottom")
    handles, labels = ax.get_legend_handles_labels()
    h2, l2 = law.get_legend_handles_labels()
    ax.legend(handles + h2, labels + l2, fontsize=6.5, loc="upper left")
    ax.set_title(f"{curve.label()}: $P(s)$ at several stresses (paper Fig. 1c)", fontsize=9)
    caption(fig, settings_caption(out, rows, swept) +
            "\nBL: $s < s_c$ (friction $\\mu_0$); HD: $s \\geq s_c$; sticking contacts ($s$ = 0) "
            "are counted in the legend, not drawn; dotted: outside the model's validity")
    save(fig, out / "plots", "fig1c_sommerfeld")


def fig1d(out, rows, curve, colours, swept):
    fig, ax = plt.subplots(figsize=(5.6, 4.2), constrained_layout=True)
    flowing = curve.flowing()
    rate = [number(r["gamma_dot"]) for r in flowing]
    bl = [number(r["frac_bl"]) for r in flowing]
    hd = [number(r["frac_hd"]) for r in flowing]
    ax.plot(rate, bl, "-", color="0.3", lw=0.8)
    ax.plot(rate, hd, "--", color="0.3", lw=0.8)
    for r, x, b, h in zip(flowing, rate, bl, hd):
        ok = r["valid"] == "true"
        colour = colours[r["dir"]] if ok else INVALID
        ax.plot([x], [b], "o", ms=6, color=colour, mfc=colour if ok else "none")
        ax.plot([x], [h], "s", ms=6, color=colour, mfc="none")
    ax.plot([], [], "o-", color="0.3", label=r"$P_{BL}$ (boundary lubricated)")
    ax.plot([], [], "s--", color="0.3", mfc="none", label=r"$P_{HD} = 1 - P_{BL}$")
    if any(r["valid"] != "true" for r in flowing):
        ax.plot([], [], "o", ls="none", mfc="none", mec=INVALID, label="outside validity")
    ax.axhline(0.2, color="0.5", ls=":", lw=0.8)
    ax.text(0.01, 0.21, "20% BL (the paper's thickening onset)", fontsize=7, color="0.4",
            transform=ax.get_yaxis_transform())
    if math.isfinite(curve.contact_onset_rate):
        # Where P_BL starts to rise for good: the onset the paper's 1/s_c
        # scaling is about (docs/analysis.md rule 8).
        ax.axvline(curve.contact_onset_rate, color="0.3", ls="-.", lw=0.8,
                   label=f"contact onset, rate {curve.contact_onset_rate:.3g} (rule 8)")
    ax.set_xscale("log")
    ax.set_ylim(0, 1)
    ax.set_xlabel(RATE)
    ax.set_ylabel("fraction of contacts")
    ax.legend(fontsize=7, loc="center left")
    ax.set_title(f"{curve.label()}: BL and HD contacts (paper Fig. 1d)", fontsize=9)
    caption(fig, settings_caption(out, rows, swept) + "\ncolours: the stresses of Fig. 1b; "
            + VALIDITY_NOTE)
    save(fig, out / "plots", "fig1d_contacts")


def draw(out):
    """The figures of the sweep in folder `out` into out/plots/."""
    out = Path(out)
    header = next(csv.reader(open(out / "flowcurves.csv", newline="")))
    swept = header[:header.index("point")]
    rows, curves = load_curves(out)
    # Pressure-imposed points (docs/sweeps.md "Pressure-imposed sweeps"): mu(J), phi(J).
    pressure = rows and mu_phi_figure(rows, settings_caption(out, rows, swept), caption, save, out)
    if not curves:
        if pressure:
            return
        raise NothingToPlot("no finished point to plot")
    flow_curves_figure(out, rows, curves, swept)
    curve = chosen_curve(curves)
    colours = stress_colours(curve)
    fig1b(out, rows, curve, colours, swept)
    fig1c(out, rows, curve, colours, swept)
    fig1d(out, rows, curve, colours, swept)


def main():
    if len(sys.argv) != 2:
        print("usage: sweep.py DIR", file=sys.stderr)
        sys.exit(2)
    try:
        draw(sys.argv[1])
    except NothingToPlot as e:
        print(e, file=sys.stderr)
        sys.exit(4)


if __name__ == "__main__":
    main()
