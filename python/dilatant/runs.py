"""dilatant.run: one simulation, as `dilatant run` does it (the library's own
run loop, so the same files and the same bits), its results as numpy arrays.
"""
import json
import os
import tempfile
import warnings
from pathlib import Path

from . import _core
from .configs import load_config
from .tables import read_table


class Result:
    """What a run produced, read back from its folder.

    summary           dict: summary.json (None when the run was interrupted)
    timeseries        structured array: timeseries.csv
    contacts          structured array: contacts.csv (final contacts)
    sommerfeld_hist   structured array: P(s), sommerfeld_hist.csv (shear cell)
    velocity_profile  structured array: velocity_profile.csv (shear cell)
    trajectory        structured array: trajectory.csv (scenes)
    samples           structured array: samples.csv (sediments)
    out               the folder (None when run with out=None: nothing kept)
    interrupted       the run stopped early (Ctrl-C, or progress returned False)
    steps, unconverged_steps, jammed; config: the resolved dilatant.Config
    """

    TABLES = ("timeseries", "contacts", "sommerfeld_hist", "velocity_profile", "trajectory",
              "samples")

    def __init__(self, config, folder, outcome, keep):
        self.config = config
        self.out = Path(folder) if keep else None
        self.interrupted = bool(outcome.get("interrupted", False))
        self.steps = outcome.get("steps")
        self.unconverged_steps = outcome.get("unconverged_steps", 0)
        self.jammed = bool(outcome.get("jammed", False))
        summary = Path(folder) / "summary.json"
        self.summary = json.loads(summary.read_text()) if summary.exists() else None
        for name in self.TABLES:
            path = Path(folder) / f"{name}.csv"
            setattr(self, name, read_table(path) if path.exists() else None)

    def __repr__(self):
        where = self.out if self.out is not None else "not kept"
        return f"<dilatant.Result {self.config.mode}, {self.steps} steps, {where}>"


def _warn_unconverged(config, outcome, keep):
    if outcome.get("unconverged_steps", 0) > 0:
        max_iterations = config.to_dict()["solver"]["max_iterations"]
        # With out=None the files are gone when the caller reads this: point to
        # what it holds instead.
        see = ("timeseries.csv, summary.json" if keep else
               "Result.timeseries['iterations'], Result.summary['frac_steps_unconverged']")
        warnings.warn(
            f"{outcome['unconverged_steps']} of {outcome['steps']} steps did not converge within "
            f"solver.max_iterations = {max_iterations} (see {see})",
            RuntimeWarning, stacklevel=4)


def run(config=None, out=None, progress=None, *, overrides=None, resume=False, start_from=None):
    """Runs one simulation and returns its Result.

    config      dict (the TOML's structure), TOML text, a path, a dilatant.Config,
                or None for the built-in default cell
    out         folder for the run's files (as `dilatant run --out`); None: a
                temporary folder, read and deleted (nothing is kept)
    progress    callable(fraction) called about ten times a second with the
                fraction done (of run.strain in a shear cell, run.time in a
                scene, the samples of a sediment); returning False stops the
                run cleanly (checkpoint written, Result.interrupted)
    overrides   `--set` values: ["friction.mu0=0.3"] or {"friction.mu0": 0.3}
    resume      continue from out/checkpoint.bin (`--resume`; a sediment keeps
                the samples it finished and runs the rest)
    start_from  a checkpoint to start from (`--start-from`)

    The GIL is released while the engine runs; Ctrl-C stops a run after the
    current step, writes its checkpoint (resume it with resume=True; a
    sediment abandons the sample it was settling) and raises
    KeyboardInterrupt. Raises ConfigError on bad input.
    """
    cfg = load_config(config, overrides)
    if resume and out is None:
        raise _core.ConfigError("resume=True needs out= (the folder holding checkpoint.bin)")
    if out is None:
        with tempfile.TemporaryDirectory(prefix="dilatant-") as folder:
            return _run_in(cfg, folder, progress, resume, start_from, keep=False)
    return _run_in(cfg, os.fspath(out), progress, resume, start_from, keep=True)


def _run_in(cfg, folder, progress, resume, start_from, keep):
    if resume and not (Path(folder) / "checkpoint.bin").exists():
        # As the CLI: a typo in out= must not silently cost a run from scratch.
        raise _core.ConfigError(
            f"{folder}: resume=True found no checkpoint.bin there; check out=, or run "
            "without resume to start anew")
    if cfg.mode == "cell":
        outcome = _core.run_cell(cfg, folder, resume, os.fspath(start_from or ""), progress)
    elif start_from:
        raise _core.ConfigError("start_from continues a shear-cell run ([cell]); "
                                f"a {cfg.mode} starts from its own configuration")
    elif cfg.mode == "scene":
        outcome = _core.run_scene(cfg, folder, resume, progress)
    else:
        outcome = _core.run_sediment(cfg, folder, resume, progress)
    _warn_unconverged(cfg, outcome, keep)
    result = Result(cfg, folder, outcome, keep)
    if result.summary is not None and result.summary.get("valid") is False:
        # As the CLI's last line: a result that is not valid says why.
        reasons = "; ".join(result.summary.get("invalid_reasons", [])) or "see the summary"
        warnings.warn(f"the result is not valid: {reasons} (Result.summary['invalid_reasons'])",
                      RuntimeWarning, stacklevel=3)
    return result
