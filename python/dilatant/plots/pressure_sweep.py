"""mu(J) and phi(J) of a pressure-imposed sweep (cell.control = "pressure";
docs/sweeps.md "Pressure-imposed sweeps"), drawn by sweep.py into
DIR/plots/mu_phi_of_J.*: mu_eff (tau / P, P imposed) and phi_bulk against the
viscous number J = eta_f gamma_dot / P, one colour per curve (sample), hollow
grey where a point is not valid, with the fits of Boyer, Guazzelli & Pouliquen
(PRL 107, 188301 (2011), their Eqs. 2-3 with mu1 0.32, mu2 0.7, J0 0.005,
phi_m 0.585) over them for comparison (theirs: frictional spheres in a viscous
fluid; a dry sweep's J is formal, I is its number)."""
import math

import matplotlib.pyplot as plt
import numpy as np

# Boyer, Guazzelli & Pouliquen 2011: mu(J) = mu1 + (mu2 - mu1) / (1 + J0 / J)
# + J + (5/2) phi_m J^(1/2), phi(J) = phi_m / (1 + J^(1/2)).
BOYER = {"mu1": 0.32, "mu2": 0.7, "J0": 0.005, "phi_m": 0.585}


def boyer_mu(j):
    b = BOYER
    shear = (b["mu2"] - b["mu1"]) / (1.0 + b["J0"] / j)
    return b["mu1"] + shear + j + 2.5 * b["phi_m"] * np.sqrt(j)


def boyer_phi(j):
    return BOYER["phi_m"] / (1.0 + np.sqrt(j))


def is_pressure(row):
    return row.get("control") == "pressure"


def _value(row, key):
    try:
        v = float(row.get(key) or "nan")
    except ValueError:
        return math.nan
    return v


def mu_phi_figure(rows, caption_text, caption, save, out):
    """Both panels from the done, pressure-controlled rows; False when none has a J."""
    points = [r for r in rows if is_pressure(r) and _value(r, "viscous_number") > 0.0]
    if not points:
        return False
    fig, (ax_mu, ax_phi) = plt.subplots(1, 2, figsize=(9.0, 3.8))
    samples = sorted({r["sample"] for r in points})
    for k, sample in enumerate(samples):
        colour = f"C{k}"
        mine = sorted((r for r in points if r["sample"] == sample),
                      key=lambda r: _value(r, "viscous_number"))
        for ax, key in ((ax_mu, "mu_eff"), (ax_phi, "phi_bulk")):
            for r in mine:
                valid = r.get("valid") == "true"
                ax.errorbar(_value(r, "viscous_number"), _value(r, key),
                            yerr=_value(r, key + "_err"), fmt="o",
                            color=colour if valid else "0.6",
                            mfc=colour if valid else "none", ms=5, capsize=2)
        ax_mu.plot([], [], "o", color=colour, label=sample)
    js = [_value(r, "viscous_number") for r in points]
    grid = np.logspace(math.log10(min(js)) - 0.5, math.log10(max(js)) + 0.5, 100)
    ax_mu.plot(grid, boyer_mu(grid), "k--", lw=1, label="Boyer et al. 2011")
    ax_phi.plot(grid, boyer_phi(grid), "k--", lw=1, label="Boyer et al. 2011")
    for ax, label in ((ax_mu, r"$\mu = \tau / P$"), (ax_phi, r"$\phi$ (bulk)")):
        ax.set_xscale("log")
        ax.set_xlabel(r"$J = \eta_f \dot\gamma / P$")
        ax.set_ylabel(label)
        ax.grid(True, which="both", lw=0.3, alpha=0.5)
    ax_mu.legend(fontsize=7)
    ax_phi.legend(fontsize=7)
    caption(fig, caption_text + "\nhollow grey: not valid (summary.json's invalid_reasons)")
    save(fig, out / "plots", "mu_phi_of_J")
    return True
