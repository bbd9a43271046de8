"""The comparison figures of docs/paper-reproduction.md that no single sweep
draws: the Stribeck curves of fig2 against the `coulomb` control, with the share
of contacts beyond s_lim under them (where the model's validity ends).

Usage: PYTHONPATH=python python3 -m dilatant.plots.coulomb_control DOCS_DIR
       (DOCS_DIR = docs/paper-reproduction)

Reads DOCS_DIR/fig2/flowcurves.csv and DOCS_DIR/coulomb/flowcurves.csv (copied
there by scripts/docs-paper.sh) and writes DOCS_DIR/control.png and .svg.
"""
import math
import sys
from pathlib import Path

from .common import RATE, VISCOSITY, plt, read_rows, save


def value(row, key):
    try:
        return float(row[key])
    except (KeyError, TypeError, ValueError):
        return math.nan


def flowing(rows, **match):
    picked = [r for r in rows if r["status"] == "done" and r["jammed"] == "false"
              and all(r[k] == v for k, v in match.items())]
    return sorted(picked, key=lambda r: value(r, "gamma_dot"))


def draw(ax, rows, colour, marker, label):
    x = [value(r, "gamma_dot") for r in rows]
    y = [value(r, "eta") for r in rows]
    ax.plot(x, y, "-", color=colour, lw=0.8, alpha=0.6)
    for xi, yi, r in zip(x, y, rows):
        valid = r["valid"] == "true"
        ax.plot(xi, yi, marker, color=colour if valid else "0.6",
                mfc=colour if valid else "none", ms=6)
    ax.plot([], [], marker, color=colour, label=label)


def main():
    if len(sys.argv) != 2:
        print(__doc__, file=sys.stderr)
        return 2
    docs = Path(sys.argv[1])
    fig2 = read_rows(docs / "fig2" / "flowcurves.csv")
    coulomb = read_rows(docs / "coulomb" / "flowcurves.csv")
    fig, (top, bottom) = plt.subplots(2, 1, figsize=(6.4, 6.4), sharex=True,
                                      gridspec_kw={"height_ratios": [2.2, 1]})
    colours = {"0.1": "#440154", "0.4": "#5ec962"}
    for mu0, colour in colours.items():
        rows = flowing(fig2, phi="0.58", mu0=mu0)
        draw(top, rows, colour, "o", f"stribeck, $\\mu_0$ = {mu0}")
        bottom.plot([value(r, "gamma_dot") for r in rows],
                    [value(r, "frac_over_slim") for r in rows], "o-", color=colour, ms=4)
    draw(top, flowing(coulomb), "#d95f02", "s", "coulomb (no hydrodynamics), $\\mu_0$ = 0.1")
    top.set_xscale("log")
    top.set_yscale("log")
    top.set_ylabel(VISCOSITY)
    top.legend(fontsize=8)
    top.set_title(r"$\phi$ = 0.58: with and without hydrodynamic lubrication", fontsize=10)
    bottom.axhline(0.05, color="0.3", ls=":", lw=1)
    bottom.text(0.99, 0.055, "validity limit: 5% beyond $s_{lim}$", fontsize=7,
                ha="right", va="bottom", transform=bottom.get_yaxis_transform())
    bottom.set_ylabel(r"contacts beyond $s_{lim}$")
    bottom.set_xlabel(RATE)
    versions = sorted({r["version"] for r in fig2 + coulomb if r.get("version")})
    fig.text(0.01, -0.01, f"dilatant {', '.join(versions)}; examples/paper/fig2.toml and "
             "coulomb.toml (25x10x27 R cell); hollow grey: valid = false",
             fontsize=6.5, ha="left", va="top", color="0.25")
    save(fig, docs, "control")
    return 0


if __name__ == "__main__":
    sys.exit(main())
