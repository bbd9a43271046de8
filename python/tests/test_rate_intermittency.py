"""dilatant.plots.rate_intermittency: a point's shear rate interval by interval
past its transient, and whether slow intervals take its time. The intervals
are equal in strain, so the time-mean rate is their harmonic mean."""
import gzip
import json
import subprocess
import sys

import pytest

from conftest import SOURCE_DIR
from dilatant.plots import rate_intermittency as ri


def series(rates, ds=0.05, start=0.0):
    """(time, strain) rows at equal strain steps ds, the interval rates given."""
    time, strain = [0.0], [start]
    for r in rates:
        time.append(time[-1] + ds / r)
        strain.append(strain[-1] + ds)
    return time, strain


def test_smooth_flow_has_no_slow_interval_and_its_time_mean_is_its_median():
    m = ri.measures(ri.interval_rates(*series([2.0] * 20), transient_strain=-1.0))  # every row
    assert m["intervals"] == 20
    assert m["cv"] == pytest.approx(0.0)
    assert m["time_mean_over_median"] == pytest.approx(1.0)
    assert (m["slow_intervals"], m["slow_time_share"]) == (0, 0.0)


def test_stops_take_the_time_and_pull_the_time_mean_down():
    # 36 intervals at rate 1, 4 at 0.2: each slow one lasts 0.25, each fast 0.05.
    m = ri.measures(ri.interval_rates(*series([1.0] * 18 + [0.2] * 4 + [1.0] * 18), -1.0))
    assert m["slow_intervals"] == 4
    assert m["slow_time_share"] == pytest.approx(1.0 / 2.8)
    assert m["time_mean_over_median"] == pytest.approx(2.0 / 2.8)  # strain 2 over time 2.8
    assert m["min_over_median"] == pytest.approx(0.2)
    # At exactly SLOW_FRACTION of the median an interval is not slow.
    edge = ri.measures(ri.interval_rates(*series([1.0] * 9 + [ri.SLOW_FRACTION]), -1.0))
    assert edge["slow_intervals"] == 0


def test_the_transient_is_left_out_as_the_summary_leaves_it():
    rates = [0.01] * 10 + [1.0] * 10  # a slow start, then smooth: strain 0.5 each
    m = ri.measures(ri.interval_rates(*series(rates), transient_strain=0.52))
    assert m["intervals"] == 9  # the rows past 0.52 bound 9 intervals
    assert m["slow_intervals"] == 0
    with pytest.raises(ValueError, match="fewer than two intervals"):
        ri.measures(ri.interval_rates(*series(rates), transient_strain=0.97))
    with pytest.raises(ValueError, match="time does not increase"):
        ri.interval_rates([0.0, 1.0, 1.0], [0.0, 0.05, 0.1], 0.0)


def point(folder, rates, gz, seed=1, transient=0.52, jammed=False):
    folder.mkdir(parents=True)
    (folder / "config.toml").write_text(
        f"[cell]\nseed = {seed}\n\n[run]\nstrain = 2.0\ntransient_strain = {transient}\n")
    summary = {"mu0": 0.4, "lambda": 146.8, "shear_stress": 21550.24, "gamma_dot": 1.74,
               "steady": False, "valid": False, "version": "0.13.1", "jammed": jammed}
    (folder / "summary.json").write_text(json.dumps(summary))
    time, strain = series(rates)
    text = "t,strain,gamma_dot\n" + "".join(f"{t},{s},0\n" for t, s in zip(time, strain))
    if gz:
        (folder / "timeseries.csv.gz").write_bytes(gzip.compress(text.encode()))
    else:
        (folder / "timeseries.csv").write_text(text)


def run(*args):
    return subprocess.run([sys.executable, "-m", "dilatant.plots.rate_intermittency", *map(str, args)],
                          capture_output=True, text=True, cwd=SOURCE_DIR / "python")


def test_the_table_reads_an_archive_and_an_output_folder_alike(tmp_path):
    stops = [1.0] * 10 + [1.0] * 14 + [0.1] * 2 + [1.0] * 14
    point(tmp_path / "runs/ramp/points/004-seed=1_lambda=146.8", stops, gz=True)
    point(tmp_path / "out/ramp/points/004-seed=1_lambda=146.8", stops, gz=False)
    for sweep in ("runs/ramp", "out/ramp"):
        done = run(tmp_path / sweep / "table", tmp_path / sweep)
        assert done.returncode == 0, done.stderr
    a, b = ((tmp_path / s / "table/intermittency.csv").read_text() for s in ("runs/ramp", "out/ramp"))
    assert a == b
    header, line = a.splitlines()
    fields = dict(zip(header.split(","), line.split(",")))
    assert (fields["seed"], fields["steady"], fields["version"]) == ("1", "false", "0.13.1")
    assert fields["intervals"] == "29"  # the rows past strain 0.52 bound 29 intervals
    assert fields["slow_intervals"] == "2"
    assert float(fields["slow_time_share"]) == pytest.approx(1.0 / (1.0 + 27 * 0.05), rel=1e-3)


def test_a_jammed_point_is_left_out(tmp_path):
    # A ramp's jam stops the cell within its transient: no interval to measure.
    point(tmp_path / "ramp/points/004-seed=1_lambda=100", [1.0] * 40, gz=False)
    point(tmp_path / "ramp/points/005-seed=1_lambda=316", [1.0] * 2, gz=False, jammed=True)
    done = run(tmp_path / "table", tmp_path / "ramp")
    assert done.returncode == 0, done.stderr
    lines = (tmp_path / "table/intermittency.csv").read_text().splitlines()
    assert [line.split(",")[1] for line in lines[1:]] == ["004-seed=1_lambda=100"]


def test_a_missing_sweep_folder_is_named(tmp_path):
    missing = run(tmp_path / "table", tmp_path / "nothing")
    assert missing.returncode != 0
    assert f"{tmp_path / 'nothing'}/points: no such folder" in missing.stderr
    assert not (tmp_path / "table").exists()
