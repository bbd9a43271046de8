"""The rheometer analysis (`dilatant analyze`, docs/analysis.md) and the
regime predictor (`dilatant predict`, docs/jamming.md)."""
import json
import os
import tempfile
import warnings
from pathlib import Path

from . import _core
from .tables import read_table


class AnalysisResult:
    """curves: curves.csv (one row per flow curve: Newtonian viscosity, onset,
    n with its interval, regime); points: points.csv (local slopes); fits:
    fits.json (per sample n - 1 = A x^-alpha and phi_max; the collapse;
    dropped_rows, the rows left out for a missing, zero or negative value);
    out: the folder (None with out=None)."""

    def __init__(self, folder, keep):
        folder = Path(folder)
        self.out = folder if keep else None
        self.curves = read_table(folder / "curves.csv")
        self.points = read_table(folder / "points.csv")
        self.fits = json.loads((folder / "fits.json").read_text())

    def __repr__(self):
        return f"<dilatant.AnalysisResult {len(self.curves)} curves, {self.out or 'not kept'}>"


def analyze(input, out=None, *, plots=True, onset_factor=None, dst_n_cap=None,
            min_window_points=None, confidence=None):
    """Analyses a manifest (.toml) or a sweep's flowcurves.csv, as `dilatant
    analyze` does; returns an AnalysisResult. Settings left None keep the
    CLI's defaults. out=None: nothing is kept (and no plots). Malformed files
    raise ConfigError with the CLI's `file:line: problem`."""
    settings = dict(onset_factor=onset_factor, dst_n_cap=dst_n_cap,
                    min_window_points=min_window_points, confidence=confidence)
    if out is None:
        with tempfile.TemporaryDirectory(prefix="dilatant-") as folder:
            _core.analyse(Path(input), folder, **settings)
            return AnalysisResult(folder, keep=False)
    _core.analyse(Path(input), os.fspath(out), **settings)
    if plots:
        try:
            from .plots import analysis as analysis_plots
            analysis_plots.draw(out)
        except ImportError as e:
            warnings.warn(f"plots skipped ({e}); the tables are complete", RuntimeWarning,
                          stacklevel=2)
    return AnalysisResult(out, keep=True)


def rheometer_steps(file):
    """The steps of a rheometer export, as `dilatant analyze --list FILE` shows
    them: one dict per step with number, name, kind ('flow curve',
    'oscillation', 'hold', 'other'), rows, points (None unless a usable flow
    curve), dropped_rows, first_line, last_line and problem (None, or why a
    flow step gives no curve). A manifest's `step = N` or `step = "name"`
    chooses among them (docs/analysis.md, "Rheometer exports")."""
    return _core.rheometer_steps(Path(file))


def predict(mu0, phi, s_c=None, table=None):
    """The flow regime ('cst', 'dst', 'no_flow') of spheres with friction mu0
    at volume fraction phi, with the margins and the onset scale: the dict of
    `dilatant predict --json`. s_c None: the Stribeck default; table None: the
    built-in phi_max_BL(mu0)."""
    return _core.predict(float(mu0), float(phi), s_c, None if table is None else Path(table))


def phase_diagram(out, table=None, plots=True):
    """`dilatant predict --grid`: out/phase_diagram.csv (and its plot); returns the table."""
    _core.phase_diagram(os.fspath(out), None if table is None else Path(table))
    if plots:
        try:
            from .plots import phase_diagram as phase_plots
            phase_plots.draw(out)
        except ImportError as e:
            warnings.warn(f"plot skipped ({e}); phase_diagram.csv is complete", RuntimeWarning,
                          stacklevel=2)
    return read_table(Path(out) / "phase_diagram.csv")
