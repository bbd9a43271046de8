"""The phase diagram of `dilatant predict --grid` (docs/jamming.md):

  python3 python/dilatant/plots/phase_diagram.py DIR
  or dilatant.plots.phase_diagram.draw(DIR)
    reads  DIR/phase_diagram.csv   the regime at every (mu0, phi) node
    writes DIR/phase_diagram.png/.svg

Regions coloured by regime (CST, DST, no flow), the nodes within 2 sigma of a
boundary (the table's error) hatched as uncertain, the nodes the bulk flow
curves decided (`source` bulk: data/jamming/bulk_flow_states.csv) as black
dots, and the paper's four
polymers (Fernandez et al. 2013, Fig. 4) as lines at their measured phi_max:
their mu0 is not in the paper's text.
"""
import sys
from pathlib import Path

if __package__:
    from .common import plt, read_rows, save
else:  # run as a script (the CLI: python3 phase_diagram.py DIR); common.py lies beside it,
    # whose folder is not on the path under python3 -P or PYTHONSAFEPATH.
    # Importing it exits 3 without matplotlib.
    sys.path.insert(0, str(Path(__file__).resolve().parent))
    from common import plt, read_rows, save  # noqa: E402

import numpy as np

PAPER = {"A": 0.578, "B": 0.560, "C": 0.555, "D": 0.545}
REGIMES = ["cst", "dst", "no_flow"]
COLOURS = ["#9ecae1", "#fdae6b", "#d9d9d9"]


def draw(out):
    out = Path(out)
    rows = read_rows(out / "phase_diagram.csv")
    mu = np.array(sorted({float(r["mu0"]) for r in rows}))
    phi = np.array(sorted({float(r["phi"]) for r in rows}))
    regime = np.zeros((len(phi), len(mu)))
    uncertain = np.zeros_like(regime)
    index_mu = {v: i for i, v in enumerate(mu)}
    index_phi = {v: j for j, v in enumerate(phi)}
    for r in rows:
        i, j = index_mu[float(r["mu0"])], index_phi[float(r["phi"])]
        regime[j, i] = REGIMES.index(r["regime"])
        uncertain[j, i] = r["uncertain"] == "true"
    from matplotlib.colors import ListedColormap

    fig, ax = plt.subplots(figsize=(6.4, 4.8))
    ax.pcolormesh(mu, phi, regime, cmap=ListedColormap(COLOURS), vmin=-0.5, vmax=2.5,
                  shading="nearest", rasterized=True)
    ax.contourf(mu, phi, uncertain, levels=[0.5, 1.5], colors="none", hatches=["...."])
    bulk = [(float(r["mu0"]), float(r["phi"])) for r in rows if r.get("source") == "bulk"]
    if bulk:
        ax.scatter(*zip(*bulk), s=4, color="k", label="measured in bulk", zorder=3)
    for collection in getattr(ax, "collections", []):
        collection.set_rasterized(True)
    for label, value in PAPER.items():
        ax.axhline(value, color="k", lw=0.6, ls=":")
        ax.text(mu[-1], value, f" {label}", va="center", fontsize=8)
    for name, colour in zip(["CST", "DST", "no flow"], COLOURS):
        ax.fill_between([], [], color=colour, label=name)
    ax.fill_between([], [], color="none", hatch="....", label="within 2 sigma")
    ax.set_xlabel(r"boundary friction $\mu_0$")
    ax.set_ylabel(r"volume fraction $\phi$")
    ax.set_title("dilatant predict --grid: bulk flow curves, else phi_max_BL(mu0)", fontsize=10)
    ax.legend(loc="lower left", fontsize=8)
    save(fig, out, "phase_diagram")


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    draw(sys.argv[1])
