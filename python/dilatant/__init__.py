"""dilatant from Python: the Contact Dynamics simulator of shear-thickening
suspensions (Fernandez et al., PRL 111, 108301, 2013) and its analysis.

    import dilatant
    r = dilatant.run({"cell": {"size": [6.0, 5.0, 7.0]}, "run": {"strain": 0.5}})
    r.summary["eta"], r.timeseries["gamma_dot"]

    cell = dilatant.ShearCell({"cell": {"phi": 0.58}})   # step by step
    cell.advance(strain=0.1); cell.positions

    dilatant.sweep("examples/paper/fig1.toml", "out/fig1", jobs=2)
    dilatant.analyze("examples/analysis/manifest.toml", "out/example")
    dilatant.predict(mu0=0.4, phi=0.59)

A configuration is a dict of the TOML's structure, TOML text or a file path;
a bad key or value raises ConfigError (a ValueError) with the message the CLI
prints after "dilatant: error: ". The compiled engine is dilatant._core
(pybind11 over libdilatant); docs/python.md has the whole workflow.
"""
__all__ = [
    "AnalysisResult", "Config", "ConfigError", "Result", "ShearCell", "SweepResult",
    "__version__", "analyze", "load_config", "phase_diagram", "predict", "read_table",
    "run", "sweep",
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
    from ._core import Config, ConfigError, __version__
    from .configs import load_config
    from .cell import ShearCell
    from .runs import Result, run
    from .sweeps import SweepResult, sweep
    from .rheology import AnalysisResult, analyze, phase_diagram, predict
    from .tables import read_table
