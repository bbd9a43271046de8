"""What the figures of dilatant.plots share (analysis, sweep, phase_diagram),
so that they are labelled, drawn and written the same way. Imported, not run.

Two ways in: as dilatant.plots.common (from Python: a missing matplotlib or
numpy raises ImportError, and the caller's backend is kept), or as the module
`common` beside a plot script that the CLI runs as `python3 FILE DIR` (then
it selects the Agg backend, and exits with status 3 and one line on stderr
when matplotlib or numpy is missing: the C++ commands report that line and
skip the plots). The docs scripts of scripts/ import it through
scripts/plot_common.py.
"""
import csv
import os
import sys


def exit_missing(error):
    """A script exits 3 with one line (the CLI reports it); Python gets the ImportError."""
    if __package__:
        raise error
    print(f"matplotlib/numpy not available ({error})", file=sys.stderr)
    sys.exit(3)


class NothingToPlot(ValueError):
    """No finished result to draw (a script exits 4)."""


# Imported by a script run from the command line, not from the package.
AS_SCRIPT = not __package__

try:
    import matplotlib

    if AS_SCRIPT:
        matplotlib.use("Agg")
    matplotlib.rcParams["svg.hashsalt"] = "dilatant"
    import matplotlib.pyplot as plt
    import numpy  # noqa: F401  (missing numpy must exit 3 too, not fail later)
except ImportError as e:  # the caller reports this line
    exit_missing(e)

# Axis labels in the simulation's units (eta_f, rho_p and R as units).
RATE = r"shear rate $\dot\gamma$ [$\eta_f/(\rho_p R^2)$]"
VISCOSITY = r"viscosity $\eta$ [$\eta_f$]"


def read_rows(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def save(fig, out, name):
    """out/name.png and .svg, each written to NAME.part and renamed, like every
    result file; closes the figure."""
    out.mkdir(parents=True, exist_ok=True)
    for ext in ("png", "svg"):
        final = out / f"{name}.{ext}"
        part = out / f"{name}.{ext}.part"
        # No date in the SVG and fixed element ids: re-drawing the same data gives the
        # same file (the docs' figures do not change when regenerated).
        metadata = {"Date": None} if ext == "svg" else None
        fig.savefig(part, format=ext, dpi=150, bbox_inches="tight", metadata=metadata)
        os.replace(part, final)
    plt.close(fig)
