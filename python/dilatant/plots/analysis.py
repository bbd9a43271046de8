#!/usr/bin/python3
"""Plots of `dilatant analyze`, drawn from its output folder (no fitting here).

Usage: python3 python/dilatant/plots/analysis.py DIR
   or: dilatant.plots.analysis.draw(DIR)
Reads DIR/curves.csv, DIR/points.csv and DIR/fits.json; writes, as PNG and SVG,
  DIR/flow_curves.*  viscosity vs shear rate, one panel per sample, colour = phi;
                     filled markers = the fit window, with the fitted power law;
                     hollow grey = outside the model's validity (simulations);
  DIR/n_vs_phi.*     n with its confidence interval vs phi, the fit
                     n - 1 = A x^-alpha per sample and phi_max (dashed);
  DIR/collapse.*     n vs the reduced fraction x = (phi_max - phi)/phi_max for all
                     samples, and n - 1 vs x in log-log with the master curve;
  DIR/wyart_cates.*  when DIR holds a Wyart–Cates fit (--model wyart-cates): the
                     model over the data and the flow-state map (wyart_cates.py).
Needs Debian's python3-matplotlib and python3-numpy; exits with status 3 and one
line on stderr when they are missing (the C++ command then reports the plots as
skipped). Files are written to NAME.part and renamed, like every result file.
"""
import json
import math
import sys
from pathlib import Path

if __package__:
    from . import wyart_cates
    from .common import RATE, VISCOSITY, read_rows, save
else:  # run as a script (the CLI: python3 analysis.py DIR); common.py lies beside it,
    # whose folder is not on the path under python3 -P or PYTHONSAFEPATH.
    # Importing it exits 3 without matplotlib.
    sys.path.insert(0, str(Path(__file__).resolve().parent))
    from common import RATE, VISCOSITY, read_rows, save  # noqa: E402
    import wyart_cates  # noqa: E402

import matplotlib  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402
import matplotlib.ticker  # noqa: E402
import numpy as np  # noqa: E402


def number(text):
    return float(text) if text not in ("", None) else math.nan


def axis_labels(units):
    if units["shear_stress"] == "Pa":
        return r"shear rate $\dot\gamma$ [1/s]", r"viscosity $\eta$ [Pa s]"
    return RATE, VISCOSITY


def flow_curves(out, samples, curves, points, units):
    cols = min(len(samples), 2)
    rows = math.ceil(len(samples) / cols)
    fig, axes = plt.subplots(rows, cols, figsize=(5.2 * cols, 4.2 * rows), squeeze=False,
                             constrained_layout=True)
    xlabel, ylabel = axis_labels(units)
    phis = [number(c["phi"]) for c in curves]
    norm = matplotlib.colors.Normalize(min(phis), max(phis) if max(phis) > min(phis) else
                                       min(phis) + 1e-3)
    cmap = matplotlib.colormaps["viridis"]
    for ax, sample in zip(axes.flat, samples):
        flowed = False  # a sample whose every point jammed has nothing to log-scale
        for index, c in enumerate(curves):
            if c["sample"] != sample:
                continue
            colour = cmap(0.85 * norm(number(c["phi"])))  # the pale end reads badly
            pts = [p for p in points if int(p["curve"]) == index]
            flowing = [p for p in pts if p["jammed"] == "false"]
            rate = np.array([number(p["shear_rate"]) for p in flowing])
            eta = np.array([number(p["viscosity"]) for p in flowing])
            valid = np.array([p["valid"] == "true" for p in flowing], dtype=bool)
            window = np.array([p["in_window"] == "true" for p in flowing], dtype=bool)
            flowed |= bool(np.any((rate > 0) & (eta > 0)))
            label = f"$\\phi$ = {c['phi']} ({c['regime']}"
            label += f", n = {number(c['n']):.2g})" if c["n"] not in ("", "inf") else ")"
            if any(p["jammed"] == "true" for p in pts):
                label += ", jams"
            ax.plot(rate[valid], eta[valid], "-", color=colour, lw=0.8, alpha=0.6)
            ax.plot(rate[valid & ~window], eta[valid & ~window], "o", ms=3, mfc="white",
                    color=colour)
            ax.plot(rate[window], eta[window], "o", ms=3.5, color=colour, label=label)
            if (~valid).any():
                ax.plot(rate[~valid], eta[~valid], "o", ms=5, mfc="none", color="0.5",
                        label="outside validity" if index == 0 else None)
            if any(p["jammed"] == "true" for p in pts) and len(rate):
                # The viscosity diverges: an arrow up from the last flowing point.
                top = np.argmax(rate)
                ax.annotate("jams", xy=(rate[top], eta[top]), xytext=(rate[top], eta[top] * 4),
                            color=colour, fontsize=7, ha="center",
                            arrowprops={"arrowstyle": "<-", "color": colour})
            k, n = number(c["consistency"]), number(c["n"])
            if math.isfinite(k) and math.isfinite(n) and window.any():
                g = np.geomspace(rate[window].min(), rate[window].max(), 20)
                ax.plot(g, k * g ** n, "--", color="k", lw=0.8)
        ax.set_xlabel(xlabel)
        ax.set_ylabel(ylabel)
        ax.set_title(f"sample {sample}")
        if not flowed:
            ax.text(0.5, 0.5, "no flowing point: every point jammed", ha="center",
                    transform=ax.transAxes, fontsize=8)
            continue
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.legend(fontsize=6, loc="upper left")
    for ax in list(axes.flat)[len(samples):]:
        ax.set_visible(False)
    fig.suptitle("Flow curves (filled: fit window; dashed: $\\eta = K\\dot\\gamma^n$)",
                 fontsize=10)
    save(fig, out, "flow_curves")


def interval(c):
    n, lo, hi = number(c["n"]), number(c["n_low"]), number(c["n_high"])
    return n, n - lo, (hi - n) if math.isfinite(hi) else 0.0


def phi_max_of(fits, sample):
    s = fits["samples"][sample]
    return s["phi_max"]


def n_vs_phi(out, samples, curves, fits):
    fig, ax = plt.subplots(figsize=(5.5, 4.2), constrained_layout=True)
    for i, sample in enumerate(samples):
        colour = f"C{i}"
        cst = [c for c in curves if c["sample"] == sample and c["regime"] == "cst"]
        dst = [c for c in curves if c["sample"] == sample and c["regime"] == "dst"]
        if cst:
            phi = [number(c["phi"]) for c in cst]
            n, lo, hi = zip(*[interval(c) for c in cst])
            ax.errorbar(phi, n, yerr=[lo, hi], fmt="o", ms=4, color=colour, capsize=2,
                        label=f"{sample}")
        s = fits["samples"][sample]
        if s["A"] is not None and s["phi_max"] is not None:
            top = s["phi_max"]
            phi = np.linspace(min(number(c["phi"]) for c in cst) - 0.005, top, 400)[:-1]
            ax.plot(phi, 1 + s["A"] * ((top - phi) / top) ** -s["alpha"], "-", color=colour,
                    lw=1)
            ax.axvline(top, color=colour, ls="--", lw=0.8)
        for c in dst:
            ax.annotate("DST", (number(c["phi"]), 0.97), xycoords=("data", "axes fraction"),
                        color=colour, fontsize=7, ha="center", va="top", rotation=90)
    ax.set_ylim(0, max([number(c["n"]) for c in curves if c["regime"] == "cst"] + [2]) * 1.4)
    ax.set_xlabel(r"volume fraction $\phi$")
    ax.set_ylabel(r"Ostwald–de Waele exponent $n$ ($\eta\propto\dot\gamma^n$)")
    ax.set_title(r"$n - 1 = A\,x^{-\alpha}$, dashed: $\phi_{max}$", fontsize=10)
    ax.legend(fontsize=8, title="sample", title_fontsize=8, loc="upper left")
    save(fig, out, "n_vs_phi")


def collapse(out, samples, curves, fits):
    c_fit = fits["collapse"]
    fig, (ax_lin, ax_log) = plt.subplots(1, 2, figsize=(10, 4.2), constrained_layout=True)
    if c_fit.get("A") is None:
        for ax in (ax_lin, ax_log):
            ax.text(0.5, 0.5, "no collapse: " + c_fit.get("note", ""), ha="center",
                    transform=ax.transAxes, fontsize=8)
        save(fig, out, "collapse")
        return
    xs_all = []
    for i, sample in enumerate(samples):
        if sample not in c_fit["phi_max"]:
            continue
        top = c_fit["phi_max"][sample]["value"]
        cst = [c for c in curves if c["sample"] == sample and c["regime"] == "cst"]
        x = np.array([(top - number(c["phi"])) / top for c in cst])
        n, lo, hi = (np.array(v) for v in zip(*[interval(c) for c in cst]))
        keep = x > 0
        xs_all += list(x[keep])
        ax_lin.errorbar(x[keep], n[keep], yerr=[lo[keep], hi[keep]], fmt="o", ms=4,
                        color=f"C{i}", capsize=2, label=sample)
        up = keep & (n > 1)
        ax_log.errorbar(x[up], n[up] - 1, yerr=[np.minimum(lo[up], n[up] - 1 - 1e-9), hi[up]],
                        fmt="o", ms=4, color=f"C{i}", capsize=2, label=sample)
    if xs_all:
        g = np.geomspace(min(xs_all) * 0.7, max(xs_all) * 1.3, 100)
        master = c_fit["A"] * g ** -c_fit["alpha"]
        # fits.json writes null for a number that is not finite (a degenerate fit).
        def shown(key, spec):
            return "-" if c_fit.get(key) is None else format(c_fit[key], spec)
        text = (f"A = {shown('A', '.3g')} ± {shown('A_err', '.2g')}, "
                f"$\\alpha$ = {shown('alpha', '.3g')} ± {shown('alpha_err', '.2g')}\n"
                f"$\\chi^2$/dof = {shown('chi2_per_dof', '.2f')}, rms deviation "
                f"{shown('rms_log10_deviation', '.3f')} decades")
        ax_lin.plot(g, 1 + master, "k-", lw=1)
        ax_log.plot(g, master, "k-", lw=1, label="master curve")
        ax_log.text(0.03, 0.04, text, transform=ax_log.transAxes, fontsize=7)
    ax_lin.set_xlabel(r"reduced fraction $x = (\phi_{max} - \phi)/\phi_{max}$")
    ax_lin.set_ylabel(r"$n$")
    ax_lin.set_xlim(left=0)
    ax_log.set_xscale("log")
    ax_log.set_yscale("log")
    # Plain numbers (0.5, 1, 2), not 5e-01; minor ticks labelled at 2, 3 and 5 only.
    plain = matplotlib.ticker.FuncFormatter(lambda v, _: f"{v:g}")
    some = matplotlib.ticker.FuncFormatter(
        lambda v, _: f"{v:g}" if round(v / 10 ** math.floor(math.log10(v))) in (2, 3, 5) else "")
    for axis in (ax_log.xaxis, ax_log.yaxis):
        axis.set_major_formatter(plain)
    ax_log.yaxis.set_minor_formatter(some)
    ax_log.set_xlabel(r"$x = (\phi_{max} - \phi)/\phi_{max}$")
    ax_log.set_ylabel(r"$n - 1$")
    ax_lin.legend(fontsize=8, title="sample", title_fontsize=8)
    ax_log.legend(fontsize=8)
    fig.suptitle("Master curve: every sample at its own $\\phi_{max}$", fontsize=10)
    save(fig, out, "collapse")


def draw(out):
    """The figures of the analysis in folder `out` (curves.csv, points.csv, fits.json)."""
    out = Path(out)
    curves = read_rows(out / "curves.csv")
    points = read_rows(out / "points.csv")
    fits = json.loads((out / "fits.json").read_text())
    samples = list(fits["samples"].keys())
    flow_curves(out, samples, curves, points, fits["units"])
    n_vs_phi(out, samples, curves, fits)
    collapse(out, samples, curves, fits)
    if (out / "wyart_cates.json").exists():
        wyart_cates.draw(out)


def main():
    if len(sys.argv) != 2:
        print("usage: analysis.py DIR", file=sys.stderr)
        sys.exit(2)
    draw(sys.argv[1])


if __name__ == "__main__":
    main()
