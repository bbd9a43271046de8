#!/usr/bin/python3
"""The Wyart–Cates fit of `dilatant analyze --model wyart-cates`, drawn from its
files (the model is evaluated in C++, src/analysis/wyart_cates_report.hpp; no
fitting here).

Usage: python3 python/dilatant/plots/wyart_cates.py DIR
   or: dilatant.plots.wyart_cates.draw(DIR)
Reads DIR/wyart_cates.json, wyart_cates_curves.csv and wyart_cates_map.csv;
writes DIR/wyart_cates.png and .svg: one row per sample (seeds pooled and
fitted: one row for their pooled fit, none for each seed alone; their scatter
is in the text),
  left   viscosity vs shear stress, one colour per phi: filled markers = fitted
         points, hollow = not fitted (outside validity, jammed), lines = the
         fitted model (Wyart & Cates, PRL 112, 098302, 2014);
  right  the flow-state map the fit implies in (phi, sigma): shaded where the
         stress-controlled flow curve turns back (DST), the shear-jamming line
         above phi_m, and phi_DST, phi_m, phi_0 with their errors.
Exits 3 with one line when matplotlib or numpy is missing, like analysis.py.
"""
import json
import math
import sys
from pathlib import Path

if __package__:
    from .common import read_rows, save
else:  # run as a script: common.py lies beside it (see analysis.py)
    sys.path.insert(0, str(Path(__file__).resolve().parent))
    from common import read_rows, save  # noqa: E402

import matplotlib  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def number(text):
    return float(text) if text not in ("", None) else math.nan


def stress_label(units):
    if units["shear_stress"] == "Pa":
        return r"shear stress $\sigma$ [Pa]", r"viscosity $\eta$ [Pa s]"
    return (r"shear stress $\sigma$ [$\eta_f^2/(\rho_p R^2)$]", r"viscosity $\eta$ [$\eta_f$]")


def with_error(value, err, digits=4):
    if value is None:
        return "-"
    text = f"{value:.{digits}g}"
    return text + (f" ± {err:.2g}" if err is not None else "")


def overlay(ax, sample, rows, fit, units):
    phis = sorted({number(r["phi"]) for r in rows})
    norm = matplotlib.colors.Normalize(min(phis), max(phis) if len(phis) > 1 else min(phis) + 1e-3)
    cmap = matplotlib.colormaps["viridis"]
    for phi in phis:
        colour = cmap(0.85 * norm(phi))
        data = [r for r in rows if number(r["phi"]) == phi and r["kind"] == "data"]
        model = [r for r in rows if number(r["phi"]) == phi and r["kind"] == "model"]
        for fitted, style in ((True, {}), (False, {"mfc": "white"})):
            pts = [r for r in data if (r["fitted"] == "true") == fitted
                   and math.isfinite(number(r["viscosity"]))]
            ax.plot([number(r["shear_stress"]) for r in pts],
                    [number(r["viscosity"]) for r in pts], "o", ms=3, color=colour,
                    label=f"$\\phi$ = {phi:.4g}" if fitted else None, **style)
        if model:
            ax.plot([number(r["shear_stress"]) for r in model],
                    [number(r["viscosity"]) for r in model], "-", color=colour, lw=1)
    xlabel, ylabel = stress_label(units)
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    if fit.get("fitted"):
        text = (f"$\\phi_0$ = {with_error(fit['phi_0'], fit['phi_0_err'])}, "
                f"$\\phi_m$ = {with_error(fit['phi_m'], fit['phi_m_err'])}\n"
                f"$\\sigma^*$ = {with_error(fit['sigma_star'], fit['sigma_star_err'])}, "
                f"A = {with_error(fit['A'], fit['A_err'])}\n"
                f"$\\alpha$ = {with_error(fit['alpha'], fit['alpha_err'], 3)} "
                f"({fit['alpha_source']}), "
                f"$\\beta$ = {with_error(fit['beta'], fit['beta_err'], 3)} "
                f"({fit['beta_source']}), "
                f"$\\chi^2$/dof = {fit['chi2_per_dof']:.3g}")
        if "seeds" in fit:
            spread = fit["seeds"]["spread"]
            text += (f"\n{len(fit['seeds']['members'])} seeds pooled; their own fits:\n"
                     + ", ".join(f"{k} {with_error(v['mean'], v['sem'])}"
                                 for k, v in spread.items()
                                 if k in ("phi_0", "phi_m", "phi_dst") and v["mean"] is not None))
        ax.text(0.03, 0.97, text, transform=ax.transAxes, fontsize=6.5, va="top")
        ax.set_title(f"sample {sample}: data and the fitted model (lines)", fontsize=9)
    else:
        ax.set_title(f"sample {sample}: no fit ({fit.get('fit_note', '')})", fontsize=7)
    # A fit in the points' measured fractions labels each curve with their mean.
    title = "bulk fraction" if fit.get("phi_basis") == "bulk" else None
    ax.legend(fontsize=5 if len(phis) > 8 else 6, ncol=2 if len(phis) > 8 else 1,
              loc="lower right", title=title, title_fontsize=6)


def state_map(ax, rows, fit):
    phi = np.array([number(r["phi"]) for r in rows])
    low = np.array([number(r["turn_low"]) for r in rows])
    high = np.array([number(r["turn_high"]) for r in rows])
    jam = np.array([number(r["shear_jamming_stress"]) for r in rows])
    s = fit["sigma_star"]
    turns = np.isfinite(low)
    ax.fill_between(phi[turns], low[turns] / s, high[turns] / s, color="C3", alpha=0.3,
                    label="turns back (DST)")
    sj = np.isfinite(jam) & (jam > 0)
    ax.plot(phi[sj], jam[sj] / s, "k-", lw=1.2, label="shear jamming")
    dst = fit["dst"]
    for key, name, style in (("phi_dst", r"$\phi_{DST}$", ":"), ("phi_m", r"$\phi_m$", "--"),
                             ("phi_0", r"$\phi_0$", "-.")):
        if dst.get(key) is not None:
            ax.axvline(dst[key], color="0.3", ls=style, lw=0.8, label=f"{name} = {dst[key]:.4f}")
    for p in fit["phi"]:
        ax.plot([p], [0.02], "|", color="C0", ms=8)  # the measured curves
    ax.set_yscale("log")
    ax.set_ylim(1e-2, 1e3)
    ax.set_xlabel(r"volume fraction $\phi$")
    ax.set_ylabel(r"$\sigma/\sigma^*$")
    err = dst.get("phi_dst_err")
    ax.set_title("flow states the fit implies" +
                 (f" ($\\phi_{{DST}}$ ± {err:.2g})" if err is not None else ""), fontsize=9)
    ax.legend(fontsize=6, loc="upper left")


def draw(out):
    """wyart_cates.png/.svg from the Wyart–Cates files in folder `out`."""
    out = Path(out)
    fits = json.loads((out / "wyart_cates.json").read_text())
    curves = read_rows(out / "wyart_cates_curves.csv")
    states = read_rows(out / "wyart_cates_map.csv")
    pooled = {m for f in fits["samples"].values() if f.get("fitted")
              for m in f.get("seeds", {}).get("members", [])}
    samples = [s for s in fits["samples"] if s not in pooled]
    fig, axes = plt.subplots(len(samples), 2, figsize=(10.5, 4.3 * len(samples)), squeeze=False,
                             constrained_layout=True)
    for (ax_curves, ax_map), sample in zip(axes, samples):
        fit = fits["samples"][sample]
        overlay(ax_curves, sample, [r for r in curves if r["sample"] == sample], fit,
                fits["units"])
        if fit.get("fitted"):
            state_map(ax_map, [r for r in states if r["sample"] == sample], fit)
        else:
            ax_map.set_visible(False)
    fig.suptitle(r"Wyart–Cates fit: $\eta = A(1 - \phi/\phi_J)^{-\alpha}$, "
                 r"$\phi_J = f\phi_m + (1-f)\phi_0$, $f = e^{-(\sigma^*/\sigma)^\beta}$",
                 fontsize=10)
    save(fig, out, "wyart_cates")


def main():
    if len(sys.argv) != 2:
        print("usage: wyart_cates.py DIR", file=sys.stderr)
        sys.exit(2)
    draw(sys.argv[1])


if __name__ == "__main__":
    main()
