"""Sweeps, the rheometer analysis and the predictor from Python give the
CLI's tables."""
import json

import numpy as np
import pytest

import dilatant
from conftest import SOURCE_DIR, TINY, run_cli

SWEEP = {**TINY, "fluid": {"lambda": [10.0, 100.0]}, "sweep": {"jobs": 1}}
SWEEP_TOML = """[cell]
size = [6.0, 5.0, 7.0]
[fluid]
lambda = [10.0, 100.0]
[run]
strain = 0.05
transient_strain = 0.01
[sweep]
jobs = 1
"""
# Columns of flowcurves.csv that are wall-clock measurements.
TIMINGS = {"wall_time_s", "wall_time_per_strain_s", "ns_per_contact_update", "peak_memory_mib"}


def same_table(a, b):
    assert a.dtype.names == b.dtype.names
    for name in a.dtype.names:
        if name not in TIMINGS:
            nan_aware = a[name].dtype.kind == "f"
            assert np.array_equal(a[name], b[name], equal_nan=nan_aware), name


def test_sweep_equals_the_cli(cli, tmp_path):
    (tmp_path / "sweep.toml").write_text(SWEEP_TOML)
    run_cli(cli, "sweep", tmp_path / "sweep.toml", "--out", tmp_path / "cli", "--quiet",
            "--no-plots")
    result = dilatant.sweep(SWEEP, tmp_path / "py", plots=False)
    assert result.outcome["done"] == 2 and result.outcome["failed"] == 0
    assert len(result.plan) == 2 and result.plan.keys == ["fluid.lambda"]
    same_table(result.flowcurves, dilatant.read_table(tmp_path / "cli" / "flowcurves.csv"))
    for label in ("000-lambda=10", "001-lambda=100"):
        a, b = (tmp_path / side / "points" / label for side in ("cli", "py"))
        assert (a / "checkpoint.bin").read_bytes() == (b / "checkpoint.bin").read_bytes()
    again = dilatant.sweep(SWEEP, tmp_path / "py", plots=False)  # resumes: nothing to run
    assert again.outcome["skipped"] == 2


def test_a_bad_sweep_names_file_line_and_key(cli, tmp_path):
    (tmp_path / "bad.toml").write_text(SWEEP_TOML.replace("lambda = [10.0", "lambda = [-1.0"))
    done = run_cli(cli, "sweep", tmp_path / "bad.toml", "--out", tmp_path / "o", check=False)
    assert done.returncode == 2
    with pytest.raises(dilatant.ConfigError) as error:
        dilatant.sweep(tmp_path / "bad.toml", tmp_path / "p")
    assert "dilatant: error: " + str(error.value) == done.stderr.strip()


def test_analysis_equals_the_cli(cli, tmp_path):
    manifest = SOURCE_DIR / "examples" / "analysis" / "manifest.toml"
    run_cli(cli, "analyze", manifest, "--out", tmp_path / "cli", "--no-plots", "--quiet")
    result = dilatant.analyze(manifest)
    assert result.out is None
    same_table(result.curves, dilatant.read_table(tmp_path / "cli" / "curves.csv"))
    assert result.fits == json.loads((tmp_path / "cli" / "fits.json").read_text())


def test_predict_equals_the_cli_json(cli):
    expected = json.loads(run_cli(cli, "predict", "--mu0", "0.4", "--phi", "0.59",
                                  "--json").stdout)
    assert dilatant.predict(mu0=0.4, phi=0.59) == expected
    assert dilatant.predict(0.1, 0.7)["regime"] == "no_flow"


def test_predict_names_its_source_as_the_cli(cli):
    """mu0 1 at phi 0.58: the bulk flow curves (Lees–Edwards) answer cst where
    the sediment table says dst; bulk_table='none' asks the sediment alone."""
    expected = json.loads(run_cli(cli, "predict", "--mu0", "1", "--phi", "0.58",
                                  "--json").stdout)
    answer = dilatant.predict(mu0=1, phi=0.58)
    assert answer == expected
    assert (answer["regime"], answer["source"]) == ("cst", "bulk flow curves")
    assert "lees-edwards-dst/flowcurves.csv" in answer["source_detail"]
    alone = dilatant.predict(mu0=1, phi=0.58, bulk_table="none")
    assert (alone["regime"], alone["source"]) == ("dst", "sediment table")


def test_phase_diagram_table(cli, tmp_path):
    run_cli(cli, "predict", "--grid", "--out", tmp_path / "cli", "--no-plots")
    table = dilatant.phase_diagram(tmp_path / "py", plots=False)
    assert (tmp_path / "py" / "phase_diagram.csv").read_bytes() == \
        (tmp_path / "cli" / "phase_diagram.csv").read_bytes()
    assert set(np.unique(table["regime"])) <= {"cst", "dst", "no_flow"}


def test_rheometer_steps_list_what_the_cli_lists(cli, tmp_path):
    """dilatant.rheometer_steps gives the steps `dilatant analyze --list` shows:
    a hold and a flow curve of a Malvern-style file."""
    rows = ["Action Name;Shear rate(1/s);Shear stress(Pa)"]
    rows += [f"Pre-shear;50;{30 + k}" for k in range(3)]
    rows += [f"Flow Curve Up;{k * k};{k * k * 0.5}" for k in range(1, 7)]
    data = tmp_path / "steps.csv"
    data.write_text("\n".join(rows) + "\n")
    steps = dilatant.rheometer_steps(data)
    assert [s["kind"] for s in steps] == ["hold", "flow curve"]
    assert [s["name"] for s in steps] == ["Pre-shear", "Flow Curve Up"]
    assert steps[0]["points"] is None and steps[1]["points"] == 6
    assert (steps[1]["first_line"], steps[1]["last_line"]) == (5, 10)
    listing = run_cli(cli, "analyze", "--list", data).stdout
    assert "Flow Curve Up" in listing and "hold" in listing
    with pytest.raises(dilatant.ConfigError, match="steps.csv:3: 4 fields, the header has 3"):
        data.write_text(rows[0] + "\n" + rows[1] + "\nPre-shear;50;31;9\n")
        dilatant.rheometer_steps(data)
