"""Progress, stopping and Ctrl-C: a run reports its fraction done, stops
cleanly when asked (checkpoint written, resumable to the uninterrupted
result), and a SIGINT in Python interrupts it the same way."""
import signal
import subprocess
import sys
import time
from pathlib import Path

import numpy as np
import pytest

import dilatant
from conftest import TINY


def test_progress_is_reported_up_to_one():
    seen = []
    dilatant.run(TINY, progress=seen.append)
    assert seen and seen[-1] >= 1.0
    assert seen == sorted(seen)


def test_progress_returning_false_stops_and_resume_completes(tmp_path):
    longer = {**TINY, "run": {"strain": 2.0, "transient_strain": 0.5}}
    stopped = dilatant.run(longer, out=tmp_path / "a", progress=lambda f: f < 0.05)
    assert stopped.interrupted and stopped.summary is None
    assert (tmp_path / "a" / "checkpoint.bin").exists()
    resumed = dilatant.run(longer, out=tmp_path / "a", resume=True)
    assert not resumed.interrupted
    whole = dilatant.run(longer, out=tmp_path / "b")
    assert np.array_equal(resumed.timeseries, whole.timeseries)
    assert (tmp_path / "a" / "checkpoint.bin").read_bytes() == \
        (tmp_path / "b" / "checkpoint.bin").read_bytes()


def test_an_exception_in_progress_stops_the_run(tmp_path):
    def fail(fraction):
        # Once stepping: raised during the set-up, it abandons the set-up and
        # nothing is written (a loaded machine's set-up outlasts the first poll).
        if fraction > 0:
            raise RuntimeError("stop here")
    longer = {**TINY, "run": {"strain": 2.0, "transient_strain": 0.5}}
    with pytest.raises(RuntimeError, match="stop here"):
        dilatant.run(longer, out=tmp_path, progress=fail)
    assert (tmp_path / "checkpoint.bin").exists()


def test_resume_needs_a_checkpoint(tmp_path):
    with pytest.raises(dilatant.ConfigError, match="found no checkpoint.bin"):
        dilatant.run(TINY, out=tmp_path, resume=True)


CHILD = """
import sys, dilatant
try:
    dilatant.run({"cell": {"size": [6.0, 5.0, 7.0]}, "run": {"strain": 1000.0}}, out=sys.argv[1],
                 progress=lambda f: print("running", flush=True) if f > 0 else None)
except KeyboardInterrupt:
    print("interrupted", flush=True)
    sys.exit(5)
"""


def test_ctrl_c_interrupts_cleanly_with_a_checkpoint(tmp_path):
    child = subprocess.Popen([sys.executable, "-c", CHILD, str(tmp_path)],
                             stdout=subprocess.PIPE, text=True)
    assert child.stdout.readline().strip() == "running"
    time.sleep(0.2)
    child.send_signal(signal.SIGINT)
    out, _ = child.communicate(timeout=30)
    assert child.returncode == 5
    assert "interrupted" in out
    assert (tmp_path / "checkpoint.bin").exists()
    assert (tmp_path / "timeseries.csv").exists()


def test_ctrl_c_stops_advance(tmp_path):
    code = ("import dilatant, sys\n"
            "cell = dilatant.ShearCell({'cell': {'size': [6.0, 5.0, 7.0]}})\n"
            "print('built', flush=True)\n"
            "try:\n"
            "    cell.advance(strain=1000.0)\n"
            "except KeyboardInterrupt:\n"
            "    cell.write_checkpoint(sys.argv[1]); sys.exit(5)\n")
    child = subprocess.Popen([sys.executable, "-c", code, str(tmp_path / "c.bin")],
                             stdout=subprocess.PIPE, text=True)
    assert child.stdout.readline().strip() == "built"
    time.sleep(0.3)
    child.send_signal(signal.SIGINT)
    child.communicate(timeout=30)
    assert child.returncode == 5
    assert dilatant.ShearCell.resumed({"cell": {"size": [6.0, 5.0, 7.0]}},
                                      tmp_path / "c.bin").steps > 0


def test_unconverged_steps_are_reported_as_a_warning(tmp_path):
    with pytest.warns(RuntimeWarning, match=r"steps did not converge within solver") as kept:
        dilatant.run(TINY, tmp_path / "kept", overrides={"solver.max_iterations": 2})
    assert any("summary.json" in str(w.message) for w in kept)
    # out=None deletes the files: the warning points to what the Result holds.
    with pytest.warns(RuntimeWarning, match=r"steps did not converge within solver") as gone:
        dilatant.run(TINY, overrides={"solver.max_iterations": 2})
    assert not any("summary.json" in str(w.message) for w in gone)
    assert any("Result.summary" in str(w.message) for w in gone)


def test_a_result_that_is_not_valid_says_why():
    with pytest.warns(RuntimeWarning, match=r"the result is not valid: .+") as caught:
        r = dilatant.run(TINY, overrides={"solver.max_iterations": 2})
    assert r.summary["valid"] is False and r.summary["invalid_reasons"]
    assert any(r.summary["invalid_reasons"][0] in str(w.message) for w in caught)


SWEEP_CHILD = """
import sys, dilatant
sweep = {"cell": {"size": [6.0, 5.0, 7.0]}, "fluid": {"lambda": [10.0, 100.0]},
         "run": {"strain": 1000.0}, "sweep": {"jobs": 2}}
print("starting", flush=True)
try:
    dilatant.sweep(sweep, sys.argv[1], plots=False)
except KeyboardInterrupt:
    sys.exit(5)
"""


def test_ctrl_c_stops_a_sweep_with_its_points_checkpointed(tmp_path):
    child = subprocess.Popen([sys.executable, "-c", SWEEP_CHILD, str(tmp_path)],
                             stdout=subprocess.PIPE, text=True)
    assert child.stdout.readline().strip() == "starting"
    time.sleep(1.0)
    child.send_signal(signal.SIGINT)
    child.communicate(timeout=30)
    assert child.returncode == 5
    table = dilatant.read_table(tmp_path / "flowcurves.csv")
    assert set(table["status"]) == {"pending"}
    assert len(list(tmp_path.glob("points/*/checkpoint.bin"))) == 2


PILE = Path(__file__).resolve().parents[2] / "examples" / "pile" / "pile.toml"


def test_a_scene_stopped_and_resumed_writes_the_uninterrupted_runs_files(tmp_path):
    stopped = dilatant.run(PILE, out=tmp_path / "a", progress=lambda f: f < 0.05,
                           overrides={"run.time": 1.0})
    assert stopped.interrupted and stopped.summary is None
    assert (tmp_path / "a" / "trajectory.csv.part").exists()
    resumed = dilatant.run(PILE, out=tmp_path / "a", resume=True, overrides={"run.time": 1.0})
    assert not resumed.interrupted
    whole = dilatant.run(PILE, out=tmp_path / "b", overrides={"run.time": 1.0})
    assert np.array_equal(resumed.trajectory, whole.trajectory)
    for name in ("trajectory.csv", "timeseries.csv", "contacts.csv"):
        assert (tmp_path / "a" / name).read_bytes() == (tmp_path / "b" / name).read_bytes()


TINY_SEDIMENT = {"sediment": {"size": [5.0, 5.0, 8.0], "samples": 2, "exclusion": 2.0},
                 "friction": {"mu0": 1.0}}


def test_a_sediment_stopped_keeps_its_finished_samples_and_resume_runs_the_rest(tmp_path):
    stopped = dilatant.run(TINY_SEDIMENT, out=tmp_path / "a", progress=lambda f: f < 0.5)
    assert stopped.interrupted and stopped.summary is None
    assert len(stopped.samples) == 1
    resumed = dilatant.run(TINY_SEDIMENT, out=tmp_path / "a", resume=True)
    whole = dilatant.run(TINY_SEDIMENT, out=tmp_path / "b")
    assert np.array_equal(resumed.samples, whole.samples)
    assert resumed.summary["phi_max"] == whole.summary["phi_max"] > 0.5
