"""dilatant.sweep: many shear cells from one sweep file (docs/sweeps.md), as
`dilatant sweep` runs them: points side by side, resumable, each curve
classified, the figures drawn.
"""
import os
import warnings
from pathlib import Path

from . import _core
from .configs import from_dict, kind, override_list, overrides_named
from .tables import read_table


class SweepResult:
    """outcome: points, done, skipped, failed, pending, above_jam, interrupted;
    flowcurves: flowcurves.csv; curves: analysis/curves.csv (the regime of
    each curve; None without a finished curve); plan: the expanded sweep
    (keys, labels, len); out: the folder."""

    def __init__(self, plan, out, outcome):
        self.plan = plan
        self.out = Path(out)
        self.outcome = outcome
        table = self.out / "flowcurves.csv"
        self.flowcurves = read_table(table) if table.exists() else None
        curves = self.out / "analysis" / "curves.csv"
        self.curves = read_table(curves) if curves.exists() else None

    def __repr__(self):
        o = self.outcome
        return f"<dilatant.SweepResult {o['done']}/{o['points']} done, {o['failed']} failed>"


def load_sweep(config, overrides=None):
    """The points of a sweep (dict, TOML text or path): a dilatant SweepPlan.
    Raises ConfigError naming the file, line, key and point."""
    return overrides_named(_load_sweep_with_sets, config, override_list(overrides))


def _load_sweep_with_sets(config, sets):
    how = kind(config)
    if how == "dict":
        return from_dict(_core.sweep_from_text, config, sets)
    if how == "path":
        return _core.sweep_from_path(Path(config), sets)
    return _core.sweep_from_text(config, "<text>", os.getcwd(), sets)


def sweep(config, out, jobs=None, *, overrides=None, plots=True, progress=None):
    """Runs (or resumes) the sweep `config` in folder `out`; returns a SweepResult.

    jobs: points side by side (None: [sweep] jobs, else one per core; 0: one
    per core). plots: draw DIR/plots/ with dilatant.plots.sweep (needs
    matplotlib; skipped with a warning otherwise). progress: callable(fraction)
    called about ten times a second with the fraction of the sweep done
    (finished points count 1, running ones their fraction of run.strain);
    returning False stops the sweep as Ctrl-C does. Ctrl-C checkpoints the
    running points and raises KeyboardInterrupt; run again to resume.
    """
    plan = load_sweep(config, overrides)
    cores = os.cpu_count() or 1
    if jobs is None:
        jobs = plan.settings.jobs if plan.settings.jobs > 0 else cores
    elif jobs == 0:
        jobs = cores
    if jobs < 0:
        raise _core.ConfigError(f"jobs = {jobs}: must be >= 0")
    outcome = _core.run_sweep(plan, os.fspath(out), int(jobs), progress)
    if outcome["done"] > 0:
        note = _core.analyse_sweep(os.fspath(out))
        if note:
            warnings.warn(f"no flow-curve analysis ({note})", RuntimeWarning, stacklevel=2)
        if plots:
            _draw(out)
    if outcome["failed"] > 0:
        warnings.warn(f"{outcome['failed']} of {outcome['points']} points failed (see the error "
                      "column of flowcurves)", RuntimeWarning, stacklevel=2)
    return SweepResult(plan, out, outcome)


def _draw(out):
    try:
        from .plots import sweep as sweep_plots
        sweep_plots.draw(out)
    except (ImportError, ValueError) as e:
        warnings.warn(f"plots skipped ({e}); the tables are complete", RuntimeWarning,
                      stacklevel=3)
