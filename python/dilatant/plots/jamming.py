"""The table and figure of docs/jamming.md from `dilatant jam` runs:

  PYTHONPATH=python python3 -m dilatant.plots.jamming OUT DOCS
    OUT/mu0-*/summary.json    one run per mu0 (scripts/docs-jamming.sh)
    OUT/shear/flowcurves.csv  the shear-jamming sweep (optional,
                              examples/jamming/shear-jamming.toml)
    OUT/shear-refine/flowcurves.csv  the points between its brackets (optional,
                              examples/jamming/shear-jamming-refine.toml)
  writes DOCS/phi_max_bl.csv  mu0, phi_max, phi_max_err, the fraction at each
                              exclusion, samples, settled, size, Stokes number,
                              version (the provenance of every row)
         DOCS/phi_max_bl.png/.svg  phi_max_BL against mu0, the regions of the
                              paper's model shaded (CST below the curve, DST
                              between it and the frictionless value, no flow
                              above), the paper's four polymers marked at their
                              measured phi_max (their mu0 is not in the paper's
                              text, so they are lines, not points), and the
                              shear-jamming phi_c(mu0) beside it
         DOCS/shear_jamming.csv  per mu0: phi_c from a straight line
                              phi_bulk = phi_c - b I through the flowing
                              points with I <= 0.1, and the densest flowing and loosest
                              jammed phi_bulk that bracket it
"""
import csv
import json
import os
import sys
from pathlib import Path

from .common import plt, save

# The shear-jamming sweeps under OUT: examples/jamming/shear-jamming.toml and
# the points between its brackets, examples/jamming/shear-jamming-refine.toml.
SHEAR_SWEEPS = ["shear", "shear-refine"]

# Flowing shear-cell points with a larger inertial number are not fitted.
MAX_INERTIAL = 0.1

# Fernandez et al. 2013, Fig. 4: phi_max of the centrifuged sediments of the
# four coatings (A-D). Their mu0 came from tribometer measurements not listed.
PAPER = {"A": 0.578, "B": 0.560, "C": 0.555, "D": 0.545}


def load(out):
    rows = []
    for d in sorted(out.glob("mu0-*")):
        f = d / "summary.json"
        if f.exists():
            with open(f) as fh:
                rows.append(json.load(fh))
    return sorted(rows, key=lambda r: r["mu0"])


def write_table(rows, docs):
    exclusions = sorted({k for r in rows for k in r["phi_by_exclusion"]}, key=float)
    head = ["mu0", "phi_max", "phi_max_err", "samples", "settled", "exclusion"]
    head += [f"phi_exclusion_{e}" for e in exclusions]
    head += ["spheres", "size", "stokes_number", "phi_initial", "max_overlap", "wall_time_s",
             "version"]
    lines = [",".join(head)]
    for r in rows:
        err = r["phi_max_err"]
        cells = [r["mu0"], f"{r['phi_max']:.5f}", "" if err is None else f"{err:.5f}",
                 len(r["seeds"]), str(r["settled"]).lower(), r["exclusion"]]
        cells += [f"{r['phi_by_exclusion'][e]['phi']:.5f}" for e in exclusions]
        cells += [r["spheres"], "x".join(f"{v:g}" for v in r["size"]), r["stokes_number"],
                  r["phi_initial"], f"{r['max_overlap']:.2e}", f"{r['wall_time_s']:.0f}",
                  r["version"]]
        lines.append(",".join(str(c) for c in cells))
    part = docs / "phi_max_bl.csv.part"
    part.write_text("\n".join(lines) + "\n")
    os.replace(part, docs / "phi_max_bl.csv")


def shear_jamming(out, docs):
    """phi_c(mu0) from the shear cell: fit and bracket, per mu0."""
    points = []
    for name in SHEAR_SWEEPS:
        table = out / name / "flowcurves.csv"
        if table.exists():
            with open(table, newline="") as f:
                points += [r for r in csv.DictReader(f) if r["status"] == "done"]
    if not points:
        return []
    result = []
    for mu0 in sorted({float(r["mu0"]) for r in points}):
        rows = [r for r in points if float(r["mu0"]) == mu0]
        # phi(I) = phi_c - b I holds in the dense, quasi-static range (I up to
        # about 0.1; da Cruz et al. 2005); faster points are left out of the fit.
        flowing = [r for r in rows if r["jammed"] == "false"
                   and float(r["inertial_number"]) <= MAX_INERTIAL]
        jammed = [r for r in rows if r["jammed"] == "true"]
        phi = [float(r["phi_bulk"]) for r in flowing]
        inertial = [float(r["inertial_number"]) for r in flowing]
        every_flowing = [float(r["phi_bulk"]) for r in rows if r["jammed"] == "false"]
        entry = {"mu0": mu0, "flowing": len(flowing), "jammed": len(jammed),
                 "phi_flowing_max": max(every_flowing) if every_flowing else None,
                 "phi_jammed_min": min(float(r["phi_bulk"]) for r in jammed) if jammed else None,
                 "phi_c": None, "slope": None}
        if len(flowing) >= 2:
            n = len(phi)
            mi, mp = sum(inertial) / n, sum(phi) / n
            sxx = sum((i - mi) ** 2 for i in inertial)
            if sxx > 0:
                b = sum((i - mi) * (p - mp) for i, p in zip(inertial, phi)) / sxx
                entry["slope"] = b
                entry["phi_c"] = mp - b * mi
        result.append(entry)
    lines = ["mu0,phi_c_fit,slope_dphi_dI,fitted_points,jammed_points,phi_bulk_flowing_max,"
             "phi_bulk_jammed_min"]
    fmt = lambda v: "" if v is None else f"{v:.5f}"
    for e in result:
        lines.append(f"{e['mu0']},{fmt(e['phi_c'])},{fmt(e['slope'])},{e['flowing']},"
                     f"{e['jammed']},{fmt(e['phi_flowing_max'])},{fmt(e['phi_jammed_min'])}")
    part = docs / "shear_jamming.csv.part"
    part.write_text("\n".join(lines) + "\n")
    os.replace(part, docs / "shear_jamming.csv")
    return result


def draw(rows, docs, shear):
    mu = [r["mu0"] for r in rows]
    phi = [r["phi_max"] for r in rows]
    err = [r["phi_max_err"] or 0.0 for r in rows]
    fig, ax = plt.subplots(figsize=(5.5, 4))
    top = 0.66
    ax.fill_between(mu, phi, [0.50] * len(mu), color="tab:blue", alpha=0.12,
                    label=r"CST: $\phi \leq \phi_{max}^{BL}(\mu_0)$")
    frictionless = [r["phi_max"] for r in rows if r["mu0"] == 0.0]
    if frictionless:
        ax.fill_between(mu, phi, [frictionless[0]] * len(mu), color="tab:red", alpha=0.12,
                        label=r"DST: up to $\phi_{max}^{HD}$ = frictionless")
        ax.axhline(frictionless[0], color="tab:red", lw=0.8)
        ax.text(0.5 * max(mu), frictionless[0] + 0.008, "no flow", ha="center", fontsize=8,
                color="tab:red")
    ax.errorbar(mu, phi, yerr=err, marker="o", capsize=3, color="k",
                label=r"sediment $\phi_{max}^{BL}$ (dilatant jam)")
    fitted = [e for e in shear if e["phi_c"] is not None]
    if fitted:
        ax.plot([e["mu0"] for e in fitted], [e["phi_c"] for e in fitted], "s", ls="none",
                color="tab:green", label=r"shear jamming $\phi_c$ (cell, I $\to$ 0)")
    for e in shear:  # a bracket only where the densest flow is looser than the loosest jam
        if (e["phi_flowing_max"] is not None and e["phi_jammed_min"] is not None
                and e["phi_jammed_min"] > e["phi_flowing_max"]):
            ax.plot([e["mu0"]] * 2, [e["phi_flowing_max"], e["phi_jammed_min"]], color="tab:green",
                    lw=3, alpha=0.4)
    for name, value in PAPER.items():
        ax.axhline(value, color="grey", ls=":", lw=0.8)
        ax.text(max(mu) if mu else 1.0, value, f" {name}", va="center", fontsize=7,
                color="grey")
    ax.set_xlabel(r"boundary friction $\mu_0$")
    ax.set_ylabel(r"$\phi_{max}$")
    ax.set_ylim(0.50, top)
    versions = sorted({r["version"] for r in rows})
    ax.set_title(f"paper's polymers A-D: dotted (their mu0 unknown); dilatant {', '.join(versions)}",
                 fontsize=7)
    ax.legend(fontsize=7, loc="lower left")
    save(fig, docs, "phi_max_bl")


def main():
    out, docs = Path(sys.argv[1]), Path(sys.argv[2])
    rows = load(out)
    if not rows:
        sys.exit(f"{out}: no mu0-*/summary.json")
    docs.mkdir(parents=True, exist_ok=True)
    write_table(rows, docs)
    shear = shear_jamming(out, docs)
    draw(rows, docs, shear)
    for r in rows:
        print(f"mu0 {r['mu0']}: phi_max {r['phi_max']:.4f} +- {r['phi_max_err'] or 0:.4f}")
    for e in shear:
        print(f"shear jamming mu0 {e['mu0']}: phi_c {e['phi_c']}, flowing up to "
              f"{e['phi_flowing_max']}, jammed from {e['phi_jammed_min']}")


if __name__ == "__main__":
    main()
