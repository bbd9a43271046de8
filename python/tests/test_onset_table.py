"""The onset table (dilatant.plots.onset_table) from `dilatant analyze`'s
contact onsets: I_c, J and frac_bl interpolated at the onset stress between
the curve's two points around it (closed form), C = gamma_dot_c s_c / I_c^2,
curves without an onset left out, a rerun replacing its curves and another
sweep's curve of the same label kept."""
import math

import pytest

from dilatant.plots import onset_table

FLOW = ("sample,cell.seed,mu0,phi,s_c,status,jammed,shear_stress,gamma_dot,frac_bl,"
        "inertial_number,viscous_number,phi_bulk,version")
CURVES = "sample,phi,contact_onset_stress,contact_onset_rate,frac_bl_min"


def sweep(folder, seeds, onset_stress=10 ** 1.5):
    """flowcurves.csv and curves.csv of curves 'mu0=0.4 seed=S': points at
    stress 1, 10, 100 (I 0.01, 0.02, 0.08; J 0.004, 0.002, 0.001; frac_bl 0.2,
    0.1, 0.3) and a jammed one at 1000; curves.csv puts the onset at
    onset_stress with rate 3 for each seed in `seeds` (None: no onset)."""
    folder.mkdir(parents=True, exist_ok=True)
    flow, curves = [FLOW], [CURVES]
    for seed in seeds:
        label = f"mu0=0.4 seed={seed}"
        for stress, rate, frac_bl, inertial, viscous in [
                (1, 0.1, 0.2, 0.01, 0.004), (10, 1.0, 0.1, 0.02, 0.002),
                (100, 4.0, 0.3, 0.08, 0.001)]:
            flow.append(f"{label},{seed},0.4,0.61,5e-05,done,false,{stress},{rate},{frac_bl},"
                        f"{inertial},{viscous},0.61,v{seed}")
        flow.append(f"{label},{seed},0.4,0.61,5e-05,done,true,1000,0,0,0,0,0.60,v{seed}")
        flow.append(f"{label},{seed},0.4,0.61,5e-05,pending,false,3000,,,,,,")
        onset = f"{onset_stress},3" if seeds[seed] else ","
        curves.append(f"{label},0.61,{onset},0.1")
    (folder / "flowcurves.csv").write_text("\n".join(flow) + "\n")
    (folder / "curves.csv").write_text("\n".join(curves) + "\n")
    return str(folder / "flowcurves.csv"), str(folder / "curves.csv")


def rows_of(lines):
    return [dict(zip(lines[0].split(","), line.split(","))) for line in lines[1:]]


def test_the_row_interpolates_at_the_onset_stress(tmp_path, capsys):
    # Onset at stress 10^1.5, half way in log between 10 and 100: I and J are
    # geometric means of their neighbours, frac_bl the arithmetic one.
    onset_table.main(["onset_table", "--header", "literal", *sweep(tmp_path, {1: True})])
    lines = capsys.readouterr().out.splitlines()
    assert lines[0] == onset_table.HEADER
    (row,) = rows_of(lines)
    assert float(row["onset_stress"]) == pytest.approx(10 ** 1.5, rel=1e-3)
    assert float(row["onset_rate"]) == 3.0
    assert float(row["inertial_number"]) == pytest.approx(0.04, rel=1e-3)
    assert float(row["viscous_number"]) == pytest.approx(math.sqrt(0.002 * 0.001), rel=1e-3)
    assert float(row["frac_bl_onset"]) == pytest.approx(0.2, abs=1e-3)
    assert float(row["prefactor"]) == pytest.approx(3.0 * 5e-5 / 0.04 ** 2, rel=1e-3)
    assert (row["frac_bl_min"], row["phi_bulk"], row["seed"]) == ("0.100", "0.6100", "1")
    assert row["source"] == f"{tmp_path} (binary v1)"


def test_a_rerun_replaces_its_curves_and_another_sweep_adds(tmp_path, capsys):
    first = sweep(tmp_path / "first", {1: True, 2: True, 3: True})
    rerun = sweep(tmp_path / "rerun", {1: True, 3: False})
    other = sweep(tmp_path / "other", {1: True})
    onset_table.main(["onset_table", "literal", *first, "--rerun", *rerun, *other])
    rows = rows_of([onset_table.HEADER] + capsys.readouterr().out.splitlines())
    # seed 1 from the rerun and the other sweep, seed 2 from the first; seed 3's
    # rerun has no onset, and replaces the first's anyway. Sorted by (mu0, seed).
    assert [(r["seed"], r["source"].split(" ")[0]) for r in rows] == [
        ("1", str(tmp_path / "rerun")), ("1", str(tmp_path / "other")), ("2", str(tmp_path / "first"))]


def test_an_onset_outside_the_flowing_points_is_an_error(tmp_path):
    with pytest.raises(ValueError, match="outside the curve's flowing points"):
        onset_table.main(["onset_table", "literal", *sweep(tmp_path, {1: True}, onset_stress=500)])
