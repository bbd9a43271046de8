"""The decisive study's Fig. 2: eta vs gamma_dot of every mu0 in the paper's
cell at phi 0.61, drawn from the tables of its several sweeps (decisive-le's
mu0 0.1 ramps, decisive-le-mu0.4's mu0 0.4 ramps run again at a converged
solver cap, decisive-le-mu0's, decisive-le-mu0.2's and decisive-le-mu0-far's
other mu0) into one figure:

    PYTHONPATH=python python3 -m dilatant.plots.decisive_fig2 DOCS FOLDER... [--name NAME]

reads DOCS/FOLDER/flowcurves.csv (its finished points), DOCS/FOLDER/curves.csv
(the regimes) and DOCS/FOLDER/sweep.toml (the solver's cap) for each FOLDER
that has them, and writes DOCS/NAME.{png,svg} (NAME: decisive-fig2). Colour is
mu0, marker the seed; a sample (mu0 and seed) found in more than one folder
is drawn from each, with a marker of its folder's and a label naming the
folder and cap: decisive-le's first mu0 0.4 run at the cap of 1000 beside the
converged rerun (docs/paper-reproduction.md "The decisive study"), or the
wall cell's ramp (decisive-walls, nominal phi 0.615) beside the Lees-Edwards
box's of the same mu0 and seed ("The wall cell"). The caption names every folder with its versions and cap.
Files are written to NAME.part and renamed, like every result file.
"""
import sys
import tomllib
from pathlib import Path

import matplotlib

from .common import NothingToPlot, number, plt, read_rows, save
from .sweep import VALIDITY_NOTE, bagnold_guide, caption, draw_curve, log_axes
from .sweep_curves import Curve

MARKERS = ["o", "s", "^", "D", "v", "P"]


def folder_curves(folder):
    """The folder's curves (its finished points by phi and sample, each with
    its analysed regime), its cap and versions; none when it has no table."""
    table = folder / "flowcurves.csv"
    if not table.exists():
        return [], None, set()
    rows = [r for r in read_rows(table) if r["status"] == "done"]
    with open(folder / "sweep.toml", "rb") as f:
        sweep = tomllib.load(f)
    cap = sweep.get("solver", {}).get("max_iterations", 1000)
    groups = {}
    for r in rows:
        groups.setdefault((number(r["phi"]), r["sample"]), []).append(r)
    curves = [Curve(phi, sample, rs) for (phi, sample), rs in groups.items()]
    if (folder / "curves.csv").exists():
        for a in read_rows(folder / "curves.csv"):
            for c in curves:
                if c.sample == a["sample"] and c.phi == number(a["phi"]):
                    c.regime, c.n, c.bagnold = a["regime"], number(a["n"]), a.get("bagnold", "")
    return curves, cap, {r["version"] for r in rows if r.get("version")}


def seed_of(curve):
    """The seed in a sample's label ("mu0=0.4 seed=2"), 1 when not swept."""
    for word in curve.sample.split(" "):
        if word.startswith("seed="):
            return int(float(word[len("seed="):]))
    return 1


def draw(docs, folders, name="decisive-fig2", title=None):
    """The figure into DOCS/NAME.*; returns the curves' labels."""
    docs = Path(docs)
    drawn, sources = [], []
    for folder in folders:
        curves, cap, versions = folder_curves(docs / folder)
        if curves:
            drawn += [(folder, cap, c) for c in curves]
            sources.append(f"{folder} (cap {cap}; dilatant {'+'.join(sorted(versions))})")
    if not drawn:
        raise NothingToPlot(f"no finished point in {', '.join(folders)} under {docs}")
    fig, ax = plt.subplots(figsize=(6.8, 5.0), constrained_layout=True)
    mu0s = sorted({c.mu0 for _, _, c in drawn})
    seeds = sorted({seed_of(c) for _, _, c in drawn})
    cmap = matplotlib.colormaps["viridis"]
    repeated = {c.sample for _, _, c in drawn
                if sum(d.sample == c.sample for _, _, d in drawn) > 1}
    labels = []
    for folder, cap, c in sorted(drawn, key=lambda item: (item[2].mu0, seed_of(item[2]),
                                                          folders.index(item[0]))):
        colour = cmap(0.85 * mu0s.index(c.mu0) / max(len(mu0s) - 1, 1))
        # A repeated curve's marker also follows its folder, so the two stay apart.
        shift = len(seeds) * folders.index(folder) if c.sample in repeated else 0
        marker = MARKERS[(seeds.index(seed_of(c)) + shift) % len(MARKERS)]
        label = c.label() + (f" [{folder}, cap {cap}]" if c.sample in repeated else "")
        draw_curve(ax, c, colour, marker, label)
        labels.append(label)
    bagnold_guide(ax, [c for _, _, c in drawn])
    log_axes(ax)
    ax.legend(fontsize=6, loc="best")
    ax.set_title(title or "The decisive study: viscosity vs shear rate per $\\mu_0$ "
                 "(paper Fig. 2, its cell)", fontsize=10)
    caption(fig, "sources: " + "; ".join(sources) + "\n" + VALIDITY_NOTE +
            "\narrow: the cell jams at the stresses above its curve's last flowing point")
    save(fig, docs, name)
    return labels


def main(argv):
    args = argv[1:]
    name = "decisive-fig2"
    if "--name" in args:
        at = args.index("--name")
        if at + 1 >= len(args):
            sys.exit(__doc__)
        name, args = args[at + 1], args[:at] + args[at + 2:]
    if len(args) < 2:
        sys.exit(__doc__)
    title = None
    if name != "decisive-fig2":
        title = "The decisive study: with walls and without (paper Fig. 2, its cell)"
    try:
        draw(args[0], args[1:], name, title)
    except NothingToPlot as e:
        print(e, file=sys.stderr)
        sys.exit(4)


if __name__ == "__main__":
    main(sys.argv)
