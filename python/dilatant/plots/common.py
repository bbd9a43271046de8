"""What the figures of dilatant.plots share (analysis, sweep, phase_diagram and
the docs' figures), so that they are labelled, drawn and written the same way.
Imported, not run.

Three ways in: as dilatant.plots.common from Python (a missing matplotlib or
numpy raises ImportError, and the caller's backend is kept); from a module run
as `python3 -m dilatant.plots.NAME` (the docs' figures); or as the module
`common` beside a plot script that the CLI runs as `python3 FILE DIR`. From a
command line it selects the Agg backend, and exits with status 3 and one line
on stderr when matplotlib or numpy is missing: the C++ commands report that
line and skip the plots.
"""
import os
import sys

if __package__:
    from .table_rows import number, read_rows  # noqa: F401  (the figures import them from here)
else:  # the plain module `common` beside a script the CLI runs, whose folder is on the path
    from table_rows import number, read_rows  # noqa: F401


def from_command_line():
    """True when a command line draws: `python3 FILE` (this file is then the
    plain module `common`) or `python3 -m dilatant.plots.NAME`."""
    if not __package__:
        return True
    spec = getattr(sys.modules.get("__main__"), "__spec__", None)
    return spec is not None and spec.name.startswith(__package__ + ".")


AS_SCRIPT = from_command_line()


def exit_missing(error):
    """A script exits 3 with one line (the CLI reports it); Python gets the ImportError."""
    if not AS_SCRIPT:
        raise error
    print(f"matplotlib/numpy not available ({error})", file=sys.stderr)
    sys.exit(3)


class NothingToPlot(ValueError):
    """No finished result to draw (a script exits 4)."""


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


def save(fig, out, name, dpi=150, tight=True):
    """out/name.png and .svg, each written to NAME.part and renamed, like every
    result file; closes the figure. dpi and tight (bbox_inches="tight") as
    the figure was first drawn: a redrawn figure keeps its size."""
    out.mkdir(parents=True, exist_ok=True)
    for ext in ("png", "svg"):
        final = out / f"{name}.{ext}"
        part = out / f"{name}.{ext}.part"
        # No date in the SVG and fixed element ids: re-drawing the same data gives the
        # same file (the docs' figures do not change when regenerated).
        metadata = {"Date": None} if ext == "svg" else None
        fig.savefig(part, format=ext, dpi=dpi, bbox_inches="tight" if tight else None,
                    metadata=metadata)
        os.replace(part, final)
    plt.close(fig)
