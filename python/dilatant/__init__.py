"""dilatant from Python: the Contact Dynamics simulator of shear-thickening
suspensions (Fernandez et al., PRL 111, 108301, 2013) and its analysis.

A run of a tiny cell (6 x 5 x 7 R, a fraction of a second; the default cell is
the paper's 25 x 10 x 27 R), its summary as a dict and its time series as
numpy arrays (out=None: in a temporary folder, removed afterwards):

>>> import dilatant
>>> tiny = {"cell": {"size": [6.0, 5.0, 7.0]},
...         "run": {"strain": 0.05, "transient_strain": 0.01}}
>>> r = dilatant.run(tiny)
>>> r.summary["eta"] > 0, r.summary["mode"]
(True, 'cell')
>>> len(r.timeseries["gamma_dot"]) > 0
True

Step by step (the GIL is released while it steps; Ctrl-C stops after a step):

>>> cell = dilatant.ShearCell(tiny)
>>> cell.advance(strain=0.01) > 0, cell.positions.shape[1]
(True, 3)

A sweep (here two points; Ctrl-C checkpoints, a second call resumes), the
rheometer analysis of the paper's Fig. 3 and the predictor:

>>> import tempfile
>>> folder = tempfile.mkdtemp()
>>> s = dilatant.sweep({**tiny, "fluid": {"lambda": [10.0, 100.0]}}, folder,
...                    jobs=1, plots=False)
>>> s.outcome["done"], len(s.flowcurves["lambda"])
(2, 2)
>>> dilatant.predict(mu0=0.4, phi=0.59)["regime"]   # from the built-in phi_max_BL(mu0)
'dst'

`dilatant.analyze("examples/analysis/manifest.toml", "out/example")` analyses
the example flow curves of the source tree (examples/analysis/).

A configuration is a dict of the TOML's structure, TOML text or a file path;
a bad key or value raises ConfigError (a ValueError) with the message the CLI
prints after "dilatant: error: ". The compiled engine is dilatant._core
(pybind11 over libdilatant); docs/python.md has the whole workflow.
"""
__all__ = [
    "AnalysisResult", "Config", "ConfigError", "Result", "Scene", "Sediment", "ShearCell",
    "SweepResult", "WyartCatesResult",
    "__version__", "analyze", "fit_wyart_cates", "load_config", "phase_diagram", "predict",
    "read_table", "rheometer_steps", "run", "sweep",
]

try:
    from . import _core
except ImportError as e:  # the source tree's python/ instead of <build>/python
    _CORE_MISSING = e

    def __getattr__(name):
        """Without _core the package still imports, for dilatant.plots (the docs'
        figures and tables: PYTHONPATH=python python3 -m dilatant.plots.NAME);
        what needs the engine says how to build it."""
        if name in __all__:
            raise ImportError(
                "dilatant's compiled part (_core) was not found: build the project "
                "(bash scripts/build.sh) and put <build>/python on PYTHONPATH, e.g. "
                "PYTHONPATH=build/python python3 (docs/python.md)") from _CORE_MISSING
        raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
else:
    try:  # every result is a numpy array: say so now, not after a run
        import numpy as _numpy  # noqa: F401
    except ImportError as _missing:
        import sys as _sys
        raise ImportError(
            f"dilatant needs numpy, which this Python ({_sys.executable}) does not have: "
            "pip install numpy, or make the venv with --system-site-packages over Debian's "
            "python3-numpy (docs/python.md)") from _missing
    from ._core import Config, ConfigError, __version__
    from .configs import load_config
    from .cell import ShearCell
    from .scene import Scene, Sediment
    from .runs import Result, run
    from .sweeps import SweepResult, sweep
    from .rheology import (AnalysisResult, WyartCatesResult, analyze, fit_wyart_cates,
                           phase_diagram, predict, rheometer_steps)
    from .tables import read_table
