"""Shared fixtures of the binding tests (run by ctest as `python_bindings`;
by hand: PYTHONPATH=build/python DILATANT_EXECUTABLE=build/dilatant
python3 -m pytest python/tests)."""
import os
import shutil
import subprocess
from pathlib import Path

import pytest

import dilatant

SOURCE_DIR = Path(__file__).resolve().parents[2]

# A shear cell that runs in a fraction of a second: 6 x 5 x 7 R to strain 0.05.
TINY = {"cell": {"size": [6.0, 5.0, 7.0]},
        "run": {"strain": 0.05, "transient_strain": 0.01}}
TINY_TOML = """[cell]
size = [6.0, 5.0, 7.0]
[run]
strain = 0.05
transient_strain = 0.01
"""


@pytest.fixture(scope="session")
def cli():
    """The dilatant executable of the same build (ctest sets DILATANT_EXECUTABLE)."""
    exe = os.environ.get("DILATANT_EXECUTABLE") or shutil.which("dilatant")
    if not exe:
        pytest.skip("set DILATANT_EXECUTABLE to the dilatant executable of this build")
    return exe


def run_cli(cli, *args, check=True):
    return subprocess.run([cli, *map(str, args)], capture_output=True, text=True, check=check)


@pytest.fixture
def tiny_file(tmp_path):
    path = tmp_path / "tiny.toml"
    path.write_text(TINY_TOML)
    return path


__all__ = ["SOURCE_DIR", "TINY", "TINY_TOML", "dilatant", "run_cli"]
