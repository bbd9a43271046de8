"""The pressure-imposed cell from Python (docs/shear-cell.md "The pressure-imposed
cell"): a run and a cell stepped by hand give Boyer, Guazzelli & Pouliquen's
quantities (mu_eff = tau / P with P imposed, phi, J, I), and the box height
follows the lid."""
import math

import pytest

import dilatant

# Dry frictional grains in the 8 x 5 x 9 R Lees-Edwards box of
# tests/drivers/pressure_cell_test.cpp, to strain 0.6: a few seconds.
PRESSURE = {
    "cell": {"boundary": "lees-edwards", "control": "pressure", "size": [8.0, 5.0, 9.0],
             "shear_rate": 0.1, "normal_stress": 2.0},
    "friction": {"law": "coulomb", "mu0": 0.4},
    "fluid": {"lambda": 1.0, "lubrication": "none", "drag": "none"},
    "run": {"strain": 0.6, "transient_strain": 0.2, "snapshot_interval": 0.0},
}

KEYS = ("normal_stress_imposed", "normal_stress", "phi_bulk", "mu_eff", "mu_pressure",
        "viscous_number", "inertial_number", "box_height_mean", "box_height_fluctuation")


def check_summary(s):
    assert s["control"] == "pressure"
    for key in KEYS:
        assert s[key] is not None and math.isfinite(s[key]), key
    assert s["normal_stress_imposed"] == pytest.approx(2.0)
    # mu_eff is tau / P with P imposed (exact); mu_pressure tau / (-tr sigma / 3).
    assert s["mu_eff_definition"] == "shear_stress_measured / normal_stress_imposed"
    assert s["mu_eff"] == pytest.approx(s["shear_stress_measured"] / s["normal_stress_imposed"],
                                        rel=1e-12)
    assert s["mu_pressure"] == pytest.approx(s["shear_stress_measured"] / s["pressure"], rel=1e-12)
    # J = eta_f gamma_dot / P and I = gamma_dot R sqrt(rho_p / P), with the
    # measured P (paper units: gamma_dot and P as summary.json gives them).
    p = s["normal_stress"]
    assert s["viscous_number"] == pytest.approx(s["eta_f"] * s["gamma_dot"] / p, rel=1e-9)
    assert 0.4 < s["phi_bulk"] < 0.66


def test_a_pressure_controlled_run_reports_mu_phi_j_and_i():
    check_summary(dilatant.run(PRESSURE).summary)


def test_a_pressure_controlled_cell_stepped_by_hand_moves_its_lid():
    cell = dilatant.ShearCell(PRESSURE)
    built = cell.box_height
    assert built == pytest.approx(9.0)
    cell.advance(strain=0.3)
    moved = cell.box_height
    assert moved != built and 0.5 * built < moved < 2.0 * built
    cell.advance(steps=10**9)
    assert cell.done
    cell.finish()
    s = cell.summary()
    check_summary(s)
    # summary.json's final height is the cell's.
    assert s["box_height"] == pytest.approx(cell.box_height, rel=1e-12)


def test_the_height_of_a_cell_under_rate_control_is_its_size():
    cell = dilatant.ShearCell({**PRESSURE, "cell": {**PRESSURE["cell"], "control": "rate",
                                                     "normal_stress": 0.0}})
    cell.advance(steps=5)
    assert cell.box_height == 9.0
    assert cell.summary()["mu_eff_definition"] == "shear_stress_measured / pressure"


def test_a_pressure_sweeps_plot_is_mu_and_phi_against_j(tmp_path):
    """The sweep's figures of pressure-imposed points: mu_phi_of_J, and no flow
    curve eta(gamma_dot) at fixed phi (their phi is measured)."""
    from dilatant.plots import sweep as sweep_plots

    header = ("cell.normal_stress,point,status,phi,sample,dir,version,mobile_spheres,control,"
              "viscous_number,mu_eff,mu_eff_err,phi_bulk,phi_bulk_err,valid,shear_stress,"
              "gamma_dot,eta,jammed")
    rows = [f"{p},{k},done,0.58,mu0=0.4,points/00{k},test,40,pressure,{0.1 / p},"
            f"{0.35 + 0.1 / p},0.02,{0.6 - 0.02 / p},0.002,{'true' if k else 'false'},"
            f"{0.4 * p},0.1,{4 * p},false"
            for k, p in enumerate([0.5, 2.0, 8.0])]
    (tmp_path / "flowcurves.csv").write_text("\n".join([header, *rows]) + "\n")
    sweep_plots.draw(tmp_path)
    assert (tmp_path / "plots" / "mu_phi_of_J.png").stat().st_size > 0
    assert not (tmp_path / "plots" / "flow_curves.png").exists()


def test_a_pressure_cell_resumed_from_its_checkpoint_goes_on_bit_for_bit(tmp_path):
    """The checkpoint keeps the lid's speed W; the contacts of the next step
    read the box's dilation rate W / H, which resuming restores (a lid still
    compacting from phi 0.51, films and drag)."""
    import numpy as np

    films = {"cell": {**PRESSURE["cell"], "phi": 0.51, "shear_rate": 0.002, "normal_stress": 1.0},
             "friction": {"law": "stribeck", "mu0": 0.4},
             "fluid": {"lambda": 0.1, "lubrication": "normal", "drag": "stokes"},
             "run": {"strain": 0.06, "transient_strain": 0.01, "snapshot_interval": 0.0}}
    whole = dilatant.ShearCell(films)
    whole.advance(strain=0.03)
    whole.write_checkpoint(tmp_path / "mid.bin")
    whole.advance(steps=10**9)
    resumed = dilatant.ShearCell.resumed(films, tmp_path / "mid.bin")
    resumed.advance(steps=10**9)
    assert resumed.steps == whole.steps
    assert resumed.box_height == whole.box_height != 9.0
    assert np.array_equal(resumed.positions, whole.positions)
    assert np.array_equal(resumed.velocities, whole.velocities)
