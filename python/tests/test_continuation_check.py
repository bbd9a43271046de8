"""scripts/continuation-check.sh: one binary against itself from a point's
state is the same physics; a binary that changes the physics (a wrapper that
sets another over-relaxation factor) is told apart; bad use is exit 2."""
import os
import stat
import subprocess

from conftest import SOURCE_DIR, run_cli

SCRIPT = SOURCE_DIR / "scripts" / "continuation-check.sh"


def check(*args):
    return subprocess.run(["bash", str(SCRIPT), *map(str, args)], capture_output=True, text=True)


def test_same_binary_same_physics_and_a_changed_one_differs(cli, tiny_file, tmp_path):
    point = tmp_path / "point"
    run_cli(cli, "run", tiny_file, "--out", point, "-q")
    same = check(cli, cli, point, 3.0, 0.03, tmp_path / "same")
    assert same.returncode == 0, same.stdout + same.stderr
    assert same.stdout.splitlines()[-1].startswith("same physics")
    assert (tmp_path / "same" / "comparison.txt").read_text() == same.stdout
    wrapper = tmp_path / "other-dilatant"
    wrapper.write_text(f'#!/bin/sh\nexec "{os.path.abspath(cli)}" "$@" --set solver.relaxation=1.0\n')
    wrapper.chmod(wrapper.stat().st_mode | stat.S_IEXEC)
    other = check(cli, wrapper, point, 3.0, 0.03, tmp_path / "other")
    assert other.returncode == 1, other.stdout + other.stderr
    assert other.stdout.splitlines()[-1].startswith("different")


def test_bad_use_is_exit_2(cli, tmp_path):
    assert check(cli, cli, tmp_path).returncode == 2
    missing = check(cli, cli, tmp_path / "nowhere", 1.0, 0.1, tmp_path / "out")
    assert missing.returncode == 2 and "no such file" in missing.stderr
