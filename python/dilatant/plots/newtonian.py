"""Figures and numbers of the Newtonian branch (docs/paper-reproduction.md
"The Newtonian branch"), from sweeps' flowcurves.csv tables:

  PYTHONPATH=python python3 -m dilatant.plots.newtonian DOCS
    DOCS/newtonian-fluid/flowcurves.csv   flow curves with fluid forces, mu0 0.1 / 0.4
    DOCS/dense-window/flowcurves.csv      the literal model's dense window (optional)
    DOCS/newtonian-phi/flowcurves.csv     eta_N at several phi (optional)
    DOCS/dense-window-phi/flowcurves.csv  the literal model against phi (optional, drawn, not fitted)
  writes DOCS/newtonian.png/.svg (eta against lambda-scaled rate per model and
  mu0) and, with newtonian-phi, DOCS/newtonian-phi/eta_n.png/.svg and
  eta_n_fit.json: the fit eta_N = A (phi_m - phi_bulk)^-beta.

The fit: for each phi_m on a grid above the largest phi_bulk, ln eta_N is a
straight line in ln(phi_m - phi_bulk), fitted by weighted least squares with
the points' own errors (sigma of ln eta = eta_err / eta); phi_m minimises chi^2,
and its error is the half-width of chi^2 <= chi^2_min + 1 times the reduced
chi^2 when that exceeds 1 (the scatter the error bars do not explain).
"""
import json
import math
import os
import sys
from pathlib import Path

from .common import plt, read_rows, save

import numpy as np


def number(row, key):
    text = row.get(key, "")
    return float(text) if text not in ("", None) else math.nan


def done(rows):
    return [r for r in rows if r.get("status") == "done" and r.get("jammed") == "false"]


def flow_curves(ax, rows, label_of, marker):
    curves = {}
    for r in done(rows):
        curves.setdefault(label_of(r), []).append(r)
    for label, points in sorted(curves.items()):
        points.sort(key=lambda r: number(r, "gamma_dot"))
        x = [number(r, "gamma_dot") for r in points]
        y = [number(r, "eta") for r in points]
        e = [number(r, "eta_err") for r in points]
        valid = [r.get("valid") == "true" for r in points]
        (line,) = ax.plot(x, y, "-", label=label)
        colour = line.get_color()
        for xs, ys, es, v in zip(x, y, e, valid):
            # Invalid points (beyond s_lim, profile, drift) drawn open.
            ax.errorbar([xs], [ys], yerr=[es], marker=marker, capsize=2, color=colour,
                        mfc=colour if v else "white", ls="none")


def fit_divergence(phi, eta, err):
    phi, eta, err = map(np.asarray, (phi, eta, err))
    sigma = np.maximum(err / eta, 1e-3)  # ln-eta errors, floored at 0.1%
    w = 1.0 / sigma**2
    best = None
    grid = np.linspace(phi.max() + 1e-4, phi.max() + 0.2, 4000)
    chi = []
    for phi_m in grid:
        x = np.log(phi_m - phi)
        a = np.vstack([np.ones_like(x), x]).T
        coef = np.linalg.solve(a.T @ (a * w[:, None]), a.T @ (w * np.log(eta)))
        c2 = float(np.sum(w * (np.log(eta) - a @ coef) ** 2))
        chi.append(c2)
        if best is None or c2 < best[0]:
            best = (c2, phi_m, coef)
    chi = np.asarray(chi)
    c2, phi_m, coef = best
    dof = max(1, len(phi) - 3)
    scale = max(1.0, c2 / dof)
    inside = grid[chi <= c2 + scale]
    return {
        "phi_m": phi_m,
        "phi_m_low": float(inside.min()),
        "phi_m_high": float(inside.max()),
        "beta": -float(coef[1]),
        "A": float(math.exp(coef[0])),
        "chi2_per_dof": c2 / dof,
        "points": len(phi),
        "at_grid_edge": bool(inside.max() >= grid[-1] - 1e-9),
    }


def main():
    docs = Path(sys.argv[1])
    fig, ax = plt.subplots(figsize=(6, 4.5))
    fluid = os.path.join(docs, "newtonian-fluid", "flowcurves.csv")
    dense = os.path.join(docs, "dense-window", "flowcurves.csv")
    if os.path.exists(fluid):
        flow_curves(ax, read_rows(fluid),
                    lambda r: f"films + drag, nominal phi {r['phi']}, mu0 {r['mu0']}", "o")
    if os.path.exists(dense):
        flow_curves(ax, [r for r in read_rows(dense) if r.get("cell.seed", "1") == "1"],
                    lambda r: f"literal, nominal phi {r['phi']}, mu0 {r['mu0']}", "s")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel(r"shear rate $\dot\gamma$ [$\eta_f/(\rho_p R^2)$]")
    ax.set_ylabel(r"viscosity $\eta$ [$\eta_f$]")
    ax.legend(fontsize=6)
    ax.set_title("Newtonian branch: open markers not valid", fontsize=9)
    save(fig, docs, "newtonian")

    phi_table = os.path.join(docs, "newtonian-phi", "flowcurves.csv")
    if not os.path.exists(phi_table):
        return
    every = done(read_rows(phi_table))
    rows = [r for r in every if r.get("valid") == "true"]
    phi = [number(r, "phi_bulk") for r in rows]
    eta = [number(r, "eta") for r in rows]
    err = [number(r, "eta_err") for r in rows]
    fig, ax = plt.subplots(figsize=(5, 4))
    ax.errorbar(phi, eta, yerr=err, marker="o", ls="none", capsize=2, label="valid")
    bad = [r for r in every if r.get("valid") != "true"]
    ax.errorbar([number(r, "phi_bulk") for r in bad], [number(r, "eta") for r in bad],
                yerr=[number(r, "eta_err") for r in bad], marker="o", mfc="white", ls="none",
                capsize=2, color="grey", label="not valid (not fitted)")
    # Three parameters: a fit needs at least four valid points.
    result = fit_divergence(phi, eta, err) if len(rows) >= 4 else {"points": len(rows),
                                                                  "fitted": False}
    part = os.path.join(docs, "newtonian-phi", "eta_n_fit.json.part")
    with open(part, "w") as f:
        json.dump(result, f, indent=2)
    os.replace(part, part[: -len(".part")])
    if "phi_m" in result:
        x = np.linspace(min(phi) - 0.01, result["phi_m"] - 0.002, 200)
        ax.plot(x, result["A"] * (result["phi_m"] - x) ** -result["beta"],
                label=rf"$A(\phi_m-\phi)^{{-{result['beta']:.2f}}}$, $\phi_m$ = {result['phi_m']:.3f}")
    literal = os.path.join(docs, "dense-window-phi", "flowcurves.csv")
    if os.path.exists(literal):  # the literal model's level, lambda 0.3 and 1 (not fitted)
        for lam, marker in (("0.3", "s"), ("1", "D")):
            pts = [r for r in done(read_rows(literal)) if r.get("lambda") == lam]
            ax.errorbar([number(r, "phi_bulk") for r in pts], [number(r, "eta") for r in pts],
                        yerr=[number(r, "eta_err") for r in pts], marker=marker, ls="none",
                        capsize=2, mfc="none", label=f"literal model, lambda {lam} (not fitted)")
    ax.set_yscale("log")
    ax.set_xlabel(r"$\phi_{bulk}$")
    ax.set_ylabel(r"$\eta_N$ [$\eta_f$]")
    ax.legend(fontsize=7)
    save(fig, docs / "newtonian-phi", "eta_n")
    print(json.dumps(result))


if __name__ == "__main__":
    main()
