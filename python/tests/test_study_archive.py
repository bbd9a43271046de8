"""scripts/study-archive.sh: a sweep saved to runs/ and restored on a bare
machine resumes as if out/ had never gone: finished points stay done, and a
continued point run again from a restored state gives the same bits."""
import fcntl
import shutil
import signal
import subprocess
import time

import pytest

from conftest import SOURCE_DIR, run_cli

SCRIPT = SOURCE_DIR / "scripts" / "study-archive.sh"

# A two-point ramp of the tiny cell: point 1 starts from point 0's checkpoint.
RAMP = """[cell]
size = [6.0, 5.0, 7.0]
[fluid]
lambda = [1.0, 3.0]
[run]
strain = 0.05
transient_strain = 0.01
snapshot_interval = 0.0
[sweep]
continuation = true
continuation_strain = 0.05
continuation_transient_strain = 0.01
"""


def archive(tmp_path, action, study="ramp"):
    env = {"PATH": "/usr/bin:/bin", "DILATANT_PAPER_OUT": str(tmp_path / "out"),
           "DILATANT_RUNS": str(tmp_path / "runs")}
    return subprocess.run(["bash", str(SCRIPT), action, study], capture_output=True,
                          text=True, env=env)


@pytest.fixture
def ramp(cli, tmp_path):
    sweep = tmp_path / "ramp.toml"
    sweep.write_text(RAMP)
    out = tmp_path / "out" / "ramp"
    run_cli(cli, "sweep", sweep, "--out", out, "--jobs", 1, "--no-plots", "--quiet")
    points = sorted((out / "points").iterdir())
    assert len(points) == 2
    return sweep, out, points


def test_restore_gives_back_what_the_sweep_needs_bit_for_bit(ramp, tmp_path):
    _, out, points = ramp
    saved = archive(tmp_path, "save")
    assert saved.returncode == 0, saved.stderr
    assert "2 point folders, 2 finished" in saved.stdout
    kept = tmp_path / "runs" / "ramp" / "points" / points[0].name
    assert (kept / "checkpoint.bin.gz").is_file()
    assert not (kept / "contacts.csv").exists()  # no table reads it
    original = {p.relative_to(out): p.read_bytes() for p in out.rglob("*") if p.is_file()}
    shutil.rmtree(tmp_path / "out")
    restored = archive(tmp_path, "restore")
    assert restored.returncode == 0, restored.stderr
    for name in ("config.toml", "summary.json", "timeseries.csv", "checkpoint.bin",
                 "velocity_profile.csv", "sommerfeld_hist.csv"):
        for point in points:
            rel = point.relative_to(out) / name
            assert (out / rel).read_bytes() == original[rel], rel
    assert not (points[0] / "contacts.csv").exists()


def test_a_restored_ramp_is_done_and_its_state_continues_exactly(ramp, tmp_path, cli):
    sweep, out, points = ramp
    series = (points[1] / "timeseries.csv").read_bytes()
    summary = (points[0] / "summary.json").read_bytes()
    assert archive(tmp_path, "save").returncode == 0
    shutil.rmtree(tmp_path / "out")
    assert archive(tmp_path, "restore").returncode == 0
    # Point 1 goes: the sweep must run it again from point 0's restored state.
    shutil.rmtree(points[1])
    again = run_cli(cli, "sweep", sweep, "--out", out, "--jobs", 1, "--no-plots")
    assert "2 done (1 of them before this run)" in again.stdout
    assert (points[1] / "timeseries.csv").read_bytes() == series
    # Point 0 was done: skipped, its restored summary untouched.
    assert (points[0] / "summary.json").read_bytes() == summary


def test_restore_never_overwrites_a_local_file(ramp, tmp_path):
    _, _, points = ramp
    assert archive(tmp_path, "save").returncode == 0
    (points[0] / "summary.json").write_text("newer\n")
    (points[1] / "checkpoint.bin").unlink()
    assert archive(tmp_path, "restore").returncode == 0
    assert (points[0] / "summary.json").read_text() == "newer\n"
    assert (points[1] / "checkpoint.bin").is_file()


def test_bad_use_is_exit_code_2(tmp_path):
    assert archive(tmp_path, "keep").returncode == 2
    missing = archive(tmp_path, "restore", study="nothing")
    assert missing.returncode == 2
    assert "runs/nothing/points: no such folder" in missing.stderr
    assert archive(tmp_path, "save", study="nothing").returncode == 2


def test_a_folder_a_sweep_runs_in_is_neither_saved_nor_restored_into(ramp, tmp_path):
    """While a sweep holds its folder's lock (src/io/folder_lock.hpp), a save
    could pair a point's older checkpoint with its newer time series: both
    actions refuse, exit 2, naming the holder; released, they work."""
    _, out, _ = ramp
    assert archive(tmp_path, "save").returncode == 0
    before = {p: p.read_bytes() for p in (tmp_path / "runs").rglob("*") if p.is_file()}
    with open(out / ".dilatant.lock", "w") as lock:
        fcntl.flock(lock, fcntl.LOCK_EX | fcntl.LOCK_NB)
        lock.write("pid 4242, a sweep, since 2026-11-29 16:29:11 UTC\n")
        lock.flush()
        for action in ("save", "restore"):
            refused = archive(tmp_path, action)
            assert refused.returncode == 2, refused.stderr
            assert refused.stderr.startswith(f"study-archive: {out}: in use by pid 4242, a sweep"), \
                refused.stderr
            assert len(refused.stderr.splitlines()) == 1
    assert {p: p.read_bytes() for p in (tmp_path / "runs").rglob("*") if p.is_file()} == before
    assert archive(tmp_path, "save").returncode == 0  # the lock released: saved as before


def test_an_interrupted_point_saved_and_restored_resumes_to_the_same_bits(cli, tmp_path):
    """A session ends mid-point (SIGTERM: the point checkpoints), the archive is
    saved, the machine is wiped, and the next one restores and resumes: the
    point ends with the bits of a run that was never stopped."""
    sweep = tmp_path / "ramp.toml"
    sweep.write_text(RAMP.replace("strain = 0.05", "strain = 4.0"))
    whole = tmp_path / "whole"
    run_cli(cli, "sweep", sweep, "--out", whole, "--jobs", 1, "--no-plots", "--quiet")
    out = tmp_path / "out" / "ramp"
    cut = subprocess.Popen([cli, "sweep", str(sweep), "--out", str(out), "--jobs", "1",
                            "--no-plots", "--quiet"], stderr=subprocess.PIPE, text=True)
    deadline = time.monotonic() + 60
    while not list(out.glob("points/001-*/checkpoint.bin")) and cut.poll() is None:
        assert time.monotonic() < deadline, "point 1 wrote no checkpoint within 60 s"
        time.sleep(0.01)
    cut.send_signal(signal.SIGTERM)
    _, err = cut.communicate(timeout=60)
    if cut.returncode == 0:
        pytest.skip("the sweep finished before SIGTERM reached it: nothing was interrupted")
    assert "1 not finished (checkpoints written)" in err, err
    assert archive(tmp_path, "save").returncode == 0
    shutil.rmtree(tmp_path / "out")
    assert archive(tmp_path, "restore").returncode == 0
    resumed = run_cli(cli, "sweep", sweep, "--out", out, "--jobs", 1, "--no-plots")
    assert "2 done (1 of them before this run)" in resumed.stdout
    for point in sorted((whole / "points").iterdir()):
        for name in ("timeseries.csv", "checkpoint.bin"):
            assert (out / "points" / point.name / name).read_bytes() == \
                (point / name).read_bytes(), f"{point.name}/{name}"


def test_a_jams_cold_start_is_kept_with_its_point(tmp_path):
    """A jammed point's cold start (points/NNN/cold-start/, sweep.confirm_jams)
    is saved and restored with its point: the table's jam_cold_start reads it."""
    point = tmp_path / "out" / "jams" / "points" / "003-lambda=1000"
    cold = point / "cold-start"
    cold.mkdir(parents=True)
    files = {point / "summary.json": b'{"jammed": true}\n', point / "checkpoint.bin": bytes(range(256)),
             cold / "summary.json": b'{"jammed": false}\n', cold / "config.toml": b"[cell]\n",
             cold / "checkpoint.bin": bytes(range(255, -1, -1)), cold / "contacts.csv": b"i,j\n"}
    for path, data in files.items():
        path.write_bytes(data)
    saved = archive(tmp_path, "save", study="jams")
    assert saved.returncode == 0, saved.stderr
    assert (tmp_path / "runs/jams/points/003-lambda=1000/cold-start/checkpoint.bin.gz").is_file()
    shutil.rmtree(tmp_path / "out")
    assert archive(tmp_path, "restore", study="jams").returncode == 0
    for path, data in files.items():
        if path.name == "contacts.csv":
            assert not path.exists()
        else:
            assert path.read_bytes() == data, path
