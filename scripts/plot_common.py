"""The plotting helpers of the docs scripts here (paper_figures.py, dst_map.py,
jamming_figures.py, newtonian_figures.py): they live in the Python package,
python/dilatant/plots/common.py, imported here as a plain module so that
these scripts run without building the package (Agg backend; exit 3 without
matplotlib). Imported, not run.
"""
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "python" / "dilatant" / "plots"))
from common import RATE, VISCOSITY, exit_missing, plt, read_rows, save  # noqa: E402,F401
