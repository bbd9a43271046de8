"""What analysis_plots.py and sweep_plots.py share, so that their figures are
labelled, drawn and written the same way. Imported by them, not run.

Importing it sets matplotlib up, or exits with status 3 and one line on stderr
when matplotlib or numpy is missing: the C++ commands that run the scripts
report that line and skip the plots.
"""
import csv
import os
import sys


def exit_missing(error):
    print(f"matplotlib/numpy not available ({error})", file=sys.stderr)
    sys.exit(3)


try:
    import matplotlib

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
