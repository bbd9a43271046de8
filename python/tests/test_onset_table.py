"""Where contacts leave the hydrodynamic branch (dilatant.plots.onset_table):
the onset is where frac_bl first rises FRAC_BL_RISE above its minimum, after
it, interpolated between the two points around the crossing; the viscosity's
own first rise and frac_bl's wanderings before its minimum do not count; a
rerun replaces its curves and another sweep's curve of the same label does
not."""
import math

import pytest

from dilatant.plots import onset_table

RISE = onset_table.FRAC_BL_RISE


def test_the_onset_is_the_crossing_above_the_minimum_interpolated():
    # frac_bl falls on the HD branch, is 0.10 at stress 100 and 0.10 + 2 RISE
    # at 1000: the crossing lies half way, at stress 10^2.5 in log; the rate
    # and I are log-log between their values there.
    points = [(1.0, 0.01, 0.30, 0.001), (10.0, 0.1, 0.20, 0.01),
              (100.0, 1.0, 0.10, 0.02), (1000.0, 4.0, 0.10 + 2 * RISE, 0.08)]
    stress, rate, (inertial,), low = onset_table.frictional_onset(reversed(points))
    assert low == 0.10
    assert stress == pytest.approx(10 ** 2.5, rel=1e-12)
    assert rate == pytest.approx(2.0, rel=1e-12)
    assert inertial == pytest.approx(0.04, rel=1e-12)


def test_a_rise_before_the_minimum_is_not_the_onset():
    # frac_bl climbs by more than RISE at low stress (contacts locking on the
    # plateau), falls to its minimum, then rises: only the last rise counts.
    points = [(1.0, 0.01, 0.20, 0.001), (10.0, 0.1, 0.20 + 2 * RISE, 0.01),
              (100.0, 1.0, 0.15, 0.02), (1000.0, 2.0, 0.15 + RISE / 2, 0.03),
              (1e4, 3.0, 0.15 + 3 * RISE, 0.04)]
    stress, _, _, low = onset_table.frictional_onset(points)
    assert low == 0.15
    t = 0.5 / 2.5  # (RISE - RISE/2) / (3 RISE - RISE/2)
    assert math.log10(stress) == pytest.approx(3 + t, rel=1e-12)


def test_no_rise_no_onset():
    points = [(1.0, 0.01, 0.3, 0.001), (10.0, 0.1, 0.2, 0.01),
              (100.0, 1.0, 0.2 + 0.9 * RISE, 0.02)]
    assert onset_table.frictional_onset(points) is None


COLUMNS = ("sample,cell.seed,mu0,s_c,status,jammed,shear_stress,gamma_dot,frac_bl,inertial_number,"
           "viscous_number,phi_bulk,version")


def sweep(path, seed_onsets):
    """A flowcurves.csv with curve 'mu0=0.4 seed=S' per seed, frac_bl rising
    past its minimum 0.1 between stresses 10 and 100 (rates 1 and rate_top)."""
    rows = []
    for seed, rate_top in seed_onsets.items():
        label = f"mu0=0.4 seed={seed}"
        for stress, rate, frac_bl in [(1, 0.1, 0.2), (10, 1.0, 0.1), (100, rate_top, 0.1 + 2 * RISE)]:
            rows.append(f"{label},{seed},0.4,5e-05,done,false,{stress},{rate},{frac_bl},0.04,0.002,0.61,v")
        rows.append(f"{label},{seed},0.4,5e-05,done,true,1000,0,0,0,0,0.6,v")  # jammed: not a point
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(COLUMNS + "\n" + "\n".join(rows) + "\n")
    return str(path)


def test_a_rerun_replaces_its_curves_and_another_sweep_adds(tmp_path, capsys):
    first = sweep(tmp_path / "first" / "flowcurves.csv", {1: 4.0, 2: 4.0})
    rerun = sweep(tmp_path / "rerun" / "flowcurves.csv", {1: 9.0})
    other = sweep(tmp_path / "other" / "flowcurves.csv", {1: 16.0})
    onset_table.main(["onset_table", "--header", "literal", first, "--rerun", rerun, other])
    lines = capsys.readouterr().out.splitlines()
    assert lines[0] == onset_table.HEADER
    rows = [dict(zip(lines[0].split(","), line.split(","))) for line in lines[1:]]
    # seed 1 from the rerun and from the other sweep, seed 2 from the first; sorted by (mu0, seed)
    assert [(r["seed"], r["source"].split(" ")[0]) for r in rows] == [
        ("1", str(tmp_path / "rerun")), ("1", str(tmp_path / "other")), ("2", str(tmp_path / "first"))]
    # the crossing is half way in frac_bl: the rate is the geometric mean of 1 and rate_top
    assert [float(r["onset_rate"]) for r in rows] == pytest.approx([3.0, 4.0, 2.0], rel=1e-3)
    assert all(r["frac_bl_min"] == "0.100" and r["phi_bulk"] == "0.6100" for r in rows)
    assert all(float(r["viscous_number"]) == pytest.approx(0.002, rel=1e-12) for r in rows)
