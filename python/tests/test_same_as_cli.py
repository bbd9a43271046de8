"""dilatant.run and the ShearCell object give the CLI's results bit for bit:
the same seed, the same files (the checkpoint is the whole state, byte for
byte), the same summary but for the wall-clock timings."""
import json
import math

import numpy as np

import dilatant
from conftest import TINY, run_cli

FILES = ["timeseries.csv", "contacts.csv", "velocity_profile.csv", "sommerfeld_hist.csv",
         "checkpoint.bin"]
# Wall-clock and memory measurements: the only fields that differ between two runs.
TIMINGS = {"time_build_s", "time_detection_s", "time_measure_s", "time_other_s", "time_solve_s",
           "wall_time_s", "wall_time_per_strain_s", "ns_per_contact_update", "peak_memory_mib"}


def summary_without_timings(path):
    return {k: v for k, v in json.loads(path.read_text()).items() if k not in TIMINGS}


def assert_same_files(a, b, names=FILES):
    for name in names:
        assert (a / name).read_bytes() == (b / name).read_bytes(), name


def cli_run(cli, tiny_file, out, *extra):
    run_cli(cli, "run", tiny_file, "--out", out, "--quiet", *extra)
    return out


def test_run_equals_the_cli(cli, tiny_file, tmp_path):
    expected = cli_run(cli, tiny_file, tmp_path / "cli")
    result = dilatant.run(TINY, out=tmp_path / "py")
    assert_same_files(expected, tmp_path / "py", FILES + ["cell.pvd"])
    # config.toml: the same keys and values; its header comment names the source.
    def body(path):
        return [line for line in path.read_text().splitlines() if not line.startswith("#")]
    assert body(expected / "config.toml") == body(tmp_path / "py" / "config.toml")
    assert summary_without_timings(expected / "summary.json") == \
        summary_without_timings(tmp_path / "py" / "summary.json")
    # The arrays are the files' numbers.
    assert result.summary["eta"] == json.loads((expected / "summary.json").read_text())["eta"]
    table = dilatant.read_table(expected / "timeseries.csv")
    assert np.array_equal(result.timeseries, table)
    assert np.array_equal(result.contacts, dilatant.read_table(expected / "contacts.csv"))
    assert result.sommerfeld_hist["fraction"].sum() > 0.99
    assert result.velocity_profile.dtype.names == ("z", "vx", "weight")


def test_overrides_and_threads_equal_the_cli(cli, tiny_file, tmp_path):
    sets = ["friction.mu0=0.3", "fluid.lambda=30", "solver.threads=2"]
    expected = cli_run(cli, tiny_file, tmp_path / "cli", *sum((["--set", s] for s in sets), []))
    dilatant.run(tiny_file, out=tmp_path / "py", overrides=sets)
    assert_same_files(expected, tmp_path / "py", FILES + ["config.toml"])


def test_without_out_nothing_is_kept_and_the_numbers_agree(cli, tiny_file, tmp_path):
    expected = cli_run(cli, tiny_file, tmp_path / "cli")
    result = dilatant.run(TINY)
    assert result.out is None
    assert np.array_equal(result.timeseries, dilatant.read_table(expected / "timeseries.csv"))
    assert result.summary["steps"] == result.steps


def test_shear_cell_step_by_step_equals_the_cli(cli, tiny_file, tmp_path):
    expected = cli_run(cli, tiny_file, tmp_path / "cli")
    cell = dilatant.ShearCell(TINY)
    n_bodies = len(cell.radii)
    assert cell.positions.shape == (n_bodies, 3)
    assert set(np.unique(cell.groups)) == {0, 1, 2}
    taken = cell.advance(steps=5)
    assert taken == 5 and cell.steps == 5
    while not cell.done:
        cell.advance(strain=0.01)
    cell.finish()
    out = tmp_path / "py"
    cell.write_results(out)
    assert_same_files(expected, out, ["timeseries.csv", "contacts.csv", "velocity_profile.csv",
                                      "sommerfeld_hist.csv"])
    assert np.array_equal(cell.timeseries, dilatant.read_table(expected / "timeseries.csv"))
    summary = cell.summary()
    assert summary["eta"] == json.loads((expected / "summary.json").read_text())["eta"]
    assert math.isfinite(cell.wall_velocity)


def test_the_cli_run_loop_in_python_gives_its_checkpoint(cli, tiny_file, tmp_path):
    # The checkpoint also holds the output schedules: keep them as the CLI does.
    expected = cli_run(cli, tiny_file, tmp_path / "cli")
    out = tmp_path / "py"
    cell = dilatant.ShearCell(TINY)
    while not cell.done:
        cell.step()
        if cell.snapshot_due:
            cell.write_snapshot(out)
        if cell.checkpoint_due:
            cell.write_checkpoint(out / "checkpoint.bin")
            cell.write_series(out)
    cell.finish()
    cell.write_checkpoint(out / "checkpoint.bin")
    cell.write_results(out)
    assert_same_files(expected, out, FILES + ["cell.pvd"])
    assert np.array_equal(cell.timeseries, dilatant.read_table(expected / "timeseries.csv"))
    summary = cell.summary()
    assert summary["eta"] == json.loads((expected / "summary.json").read_text())["eta"]
    assert math.isfinite(cell.wall_velocity)


def test_resumed_cell_continues_exactly(cli, tiny_file, tmp_path):
    expected = cli_run(cli, tiny_file, tmp_path / "cli")
    cell = dilatant.ShearCell(TINY)
    cell.advance(steps=10)
    cell.write_checkpoint(tmp_path / "half.bin")
    resumed = dilatant.ShearCell.resumed(TINY, tmp_path / "half.bin")
    assert resumed.steps == 10
    resumed.advance(strain=1.0)
    resumed.finish()
    resumed.write_results(tmp_path / "py")
    assert_same_files(expected, tmp_path / "py", ["timeseries.csv", "contacts.csv"])


def test_lees_edwards_cell_equals_the_cli(cli, tiny_file, tmp_path):
    # The wall-free cell (docs/shear-cell.md "The Lees–Edwards cell") from
    # Python: the same bits as the CLI, no wall bodies, null wall forces, and
    # wall_velocity the images' speed.
    le = "cell.boundary=lees-edwards"
    expected = cli_run(cli, tiny_file, tmp_path / "cli", "--set", le)
    cell = dilatant.ShearCell(TINY, overrides=[le])
    assert set(np.unique(cell.groups)) == {0}
    while not cell.done:
        cell.step()
    cell.finish()
    out = tmp_path / "py"
    cell.write_results(out)
    assert_same_files(expected, out, ["timeseries.csv", "contacts.csv", "velocity_profile.csv"])
    summary = cell.summary()
    assert summary["boundary"] == "lees-edwards"
    assert summary["bottom_wall_force_x"] is None
    assert summary["eta"] == json.loads((expected / "summary.json").read_text())["eta"]
    assert cell.wall_velocity > 0.0
