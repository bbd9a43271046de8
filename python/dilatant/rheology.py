"""The rheometer analysis (`dilatant analyze`, docs/analysis.md), the
Wyart–Cates fit (`dilatant analyze --model wyart-cates`) and the regime
predictor (`dilatant predict`, docs/jamming.md)."""
import importlib
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


def _write_and_read(write, result, plot_module, input, out, plots, settings, skipped):
    """Runs `write(input, folder, **settings)` (a _core function that writes its
    tables into folder) into `out`, or into a temporary folder when out is None
    (then nothing is kept, no plot); draws dilatant.plots.<plot_module> when
    asked; returns result(folder, keep)."""
    if out is None:
        with tempfile.TemporaryDirectory(prefix="dilatant-") as folder:
            write(Path(input), folder, **settings)
            return result(folder, keep=False)
    write(Path(input), os.fspath(out), **settings)
    if plots:
        try:
            importlib.import_module(f".plots.{plot_module}", __package__).draw(out)
        except ImportError as e:
            warnings.warn(f"{skipped} ({e}); the tables are complete", RuntimeWarning,
                          stacklevel=3)
    return result(out, keep=True)


def analyze(input, out=None, *, plots=True, onset_factor=None, dst_n_cap=None,
            min_window_points=None, confidence=None):
    """Analyses a manifest (.toml) or a sweep's flowcurves.csv, as `dilatant
    analyze` does; returns an AnalysisResult. Settings left None keep the
    CLI's defaults. out=None: nothing is kept (and no plots). Malformed files
    raise ConfigError with the CLI's `file:line: problem`."""
    settings = dict(onset_factor=onset_factor, dst_n_cap=dst_n_cap,
                    min_window_points=min_window_points, confidence=confidence)
    return _write_and_read(_core.analyse, AnalysisResult, "analysis", input, out, plots,
                           settings, "plots skipped")


def rheometer_steps(file):
    """The steps of a rheometer export, as `dilatant analyze --list FILE` shows
    them: one dict per step with number, name, kind ('flow curve',
    'oscillation', 'hold', 'other'), rows, points (None unless a usable flow
    curve), dropped_rows, first_line, last_line and problem (None, or why a
    flow step gives no curve). A manifest's `step = N` or `step = "name"`
    chooses among them (docs/analysis.md, "Rheometer exports")."""
    return _core.rheometer_steps(Path(file))


class WyartCatesResult:
    """fit: wyart_cates.json (per sample phi_0, phi_m, sigma_star, A, alpha, beta
    with errors, chi2_per_dof, and `dst`: phi_dst with its error); curves:
    wyart_cates_curves.csv (data and model, the overlay); map:
    wyart_cates_map.csv (the flow states the fit implies over phi); out: the
    folder (None with out=None)."""

    def __init__(self, folder, keep):
        folder = Path(folder)
        self.out = folder if keep else None
        self.fit = json.loads((folder / "wyart_cates.json").read_text())
        self.curves = read_table(folder / "wyart_cates_curves.csv")
        self.map = read_table(folder / "wyart_cates_map.csv")

    def __repr__(self):
        fitted = sum(1 for s in self.fit["samples"].values() if s["fitted"])
        return f"<dilatant.WyartCatesResult {fitted} fitted samples, {self.out or 'not kept'}>"


def fit_wyart_cates(input, out=None, *, alpha=None, beta=None, fit_alpha=False, fit_beta=False,
                    phi_basis="auto", weights="auto", plots=True):
    """Fits the Wyart–Cates model (phi_0, phi_m, sigma*, A; alpha and beta held
    at 2 and 1 unless fit_alpha/fit_beta, or held at the values given) to each
    sample of a manifest (.toml) or a sweep's flowcurves.csv, as `dilatant
    analyze --model wyart-cates`; returns a WyartCatesResult. out=None: nothing
    is kept (and no plot). No sample fitted raises ConfigError with each
    sample's reason.

    phi_basis, the volume fraction fitted (`--wc-phi`): 'bulk', each point's
    measured phi_bulk (a sweep table's; a point without one refuses the fit),
    'nominal', each curve's phi, or 'auto', bulk when every fitted point of
    the input has one, else nominal. weights, the residuals' (`--wc-weights`):
    'auto', the rate errors when every point has one, else uniform;
    'uniform'; or 'errors', each point's error of eta (gamma_dot_err, or
    eta_err at an imposed rate; a point without one refuses the fit). Another
    value raises ConfigError naming the argument and the allowed ones. The
    JSON says which basis each sample was fitted in (`phi_basis`)."""
    settings = dict(alpha=alpha, beta=beta, fit_alpha=bool(fit_alpha), fit_beta=bool(fit_beta),
                    phi=str(phi_basis), weights=str(weights))
    return _write_and_read(_core.fit_wyart_cates, WyartCatesResult, "wyart_cates", input, out,
                           plots, settings, "plot skipped")


def predict(mu0=None, phi=None, s_c=None, table=None, *, model=None, stress=None, sample=None,
            bulk_table=None):
    """The flow regime ('cst', 'dst', 'no_flow') of spheres with friction mu0
    at volume fraction phi, with the margins and the frictional onset: the dict of
    `dilatant predict --json`. The regime comes from the flow states measured
    in bulk (Lees–Edwards ramps) where they decide, else from the sediment's
    phi_max_BL(mu0); `source` says which ('bulk flow curves' or 'sediment
    table') and `source_detail` which row or why. s_c None: the Stribeck
    default; table None: the built-in phi_max_BL(mu0); bulk_table None: the
    built-in bulk flow states, 'none': the sediment table alone.

    With model (a wyart_cates.json of fit_wyart_cates or `analyze --model
    wyart-cates`): the regime from that fit instead ('cst', 'dst',
    'shear_jamming', 'no_flow'), and with stress the state of the
    stress-controlled flow there: the dict of `dilatant predict --model FILE
    --json`; sample chooses among several fitted samples (default: the only
    one, or the pooled fit of one suspension's seeds). phi is then read in
    the fit's basis, the JSON's `phi_basis`: the bulk fraction (a sweep's
    phi_bulk, below a wall cell's nominal phi) when the fit was in bulk phi,
    else the nominal one. `source` in the dict says which answered."""
    if phi is None:
        raise TypeError("predict() needs phi")
    if model is not None:
        if mu0 is not None or table is not None or s_c is not None or bulk_table is not None:
            raise TypeError("predict(): model= answers from the fit; mu0, s_c, table and "
                            "bulk_table are the tables'")
        return _core.predict_from_fit(Path(model), float(phi),
                                      None if stress is None else float(stress), sample or "")
    if stress is not None or sample is not None:
        raise TypeError("predict(): stress and sample need model=")
    if mu0 is None:
        raise TypeError("predict() needs mu0 (or model=)")
    return _core.predict(float(mu0), float(phi), s_c, None if table is None else Path(table),
                         None if bulk_table is None else os.fspath(bulk_table))


def phase_diagram(out, table=None, plots=True, bulk_table=None):
    """`dilatant predict --grid`: out/phase_diagram.csv (and its plot); returns the table.
    Its `source` column says which table decided each node ('bulk' or 'sediment')."""
    _core.phase_diagram(os.fspath(out), None if table is None else Path(table),
                        None if bulk_table is None else os.fspath(bulk_table))
    if plots:
        try:
            from .plots import phase_diagram as phase_plots
            phase_plots.draw(out)
        except ImportError as e:
            warnings.warn(f"plot skipped ({e}); phase_diagram.csv is complete", RuntimeWarning,
                          stacklevel=2)
    return read_table(Path(out) / "phase_diagram.csv")
