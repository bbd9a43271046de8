"""The package as `pip install .` leaves it (scripts/pip-check.sh): the
`dilatant` command on the environment's PATH is the engine inside the package,
and it draws its plots with the package's scripts and this environment's
Python. Skipped when the module is imported from a build folder."""
import sys
from pathlib import Path

import pytest

import dilatant
from conftest import SOURCE_DIR, run_cli

PACKAGE = Path(dilatant.__file__).resolve().parent
INSTALLED = (PACKAGE / "_bin" / "dilatant").is_file()
pytestmark = pytest.mark.skipif(not INSTALLED, reason="not an installed package (pip install .)")


def test_the_command_is_the_packages_engine(cli):
    assert Path(cli).resolve().is_relative_to(Path(sys.prefix).resolve())
    assert run_cli(cli, "--version").stdout.strip().endswith(dilatant.__version__)


def test_the_command_draws_with_the_packages_plot_scripts(cli, tmp_path):
    done = run_cli(cli, "analyze", SOURCE_DIR / "examples" / "analysis" / "manifest.toml",
                   "--out", tmp_path / "a", "--quiet")
    assert "plots skipped" not in done.stderr, done.stderr
    assert list((tmp_path / "a").rglob("*.png")), "no figure drawn"
    assert (PACKAGE / "plots" / "analysis.py").is_file()


def test_the_type_stubs_are_installed():
    assert (PACKAGE / "_core.pyi").is_file() and (PACKAGE / "py.typed").is_file()
