"""The table and figure of docs/jamming.md from `dilatant jam` runs:

  jamming_figures.py OUT DOCS
    OUT/mu0-*/summary.json    one run per mu0 (scripts/docs-jamming.sh)
  writes DOCS/phi_max_bl.csv  mu0, phi_max, phi_max_err, the fraction at each
                              exclusion, samples, settled, size, Stokes number,
                              version (the provenance of every row)
         DOCS/phi_max_bl.png/.svg  phi_max_BL against mu0, the regions of the
                              paper's model shaded (CST below the curve, DST
                              between it and the frictionless value, no flow
                              above), the paper's four polymers marked at their
                              measured phi_max (their mu0 is not in the paper's
                              text, so they are lines, not points)
"""
import json
import os
import sys
from pathlib import Path

from plot_common import plt, save

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


def draw(rows, docs):
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
    draw(rows, docs)
    for r in rows:
        print(f"mu0 {r['mu0']}: phi_max {r['phi_max']:.4f} +- {r['phi_max_err'] or 0:.4f}")


if __name__ == "__main__":
    main()
