"""The decisive study's tables: dilatant.plots.contact_states reads each
finished, flowing point's sticking share from the s = 0 row of its
sommerfeld_hist.csv, beside frac_bl, and refuses a histogram whose first row is
another bin; dilatant.plots.ramp_table writes the points' table with the marker
the docs check reads."""
import pytest

from dilatant.plots import contact_states

COLUMNS = "sample,phi,mu0,lambda,shear_stress,eta,frac_bl,mu_eff,pressure,version,status,jammed,dir"


def point(folder, name, stick):
    (folder / name).mkdir(parents=True)
    (folder / name / "sommerfeld_hist.csv").write_text(
        f"s_low,s_high,count,fraction\n0,0,10,{stick}\n0,1e-10,0,0\n")


def test_sticking_share_beside_frac_bl(tmp_path):
    (tmp_path / "flowcurves.csv").write_text(COLUMNS + "\n" + "\n".join([
        "mu0=0.4,0.61,0.4,1,1,99,0.29,0.30,3.3,0.8.0,done,false,points/a",
        "mu0=0.4,0.61,0.4,10,100,,,,,0.8.0,done,true,points/b",   # jammed: no row
        "mu0=0.4,0.61,0.4,100,,,,,,,pending,,points/c"]) + "\n")
    point(tmp_path, "points/a", 0.28)
    point(tmp_path, "points/b", 0.5)
    rows = contact_states.rows(tmp_path)
    assert len(rows) == 1
    fields = dict(zip(contact_states.HEADER.split(","), rows[0].split(",")))
    assert fields["frac_stick"] == "0.28"
    assert float(fields["stick_share_of_bl"]) == pytest.approx(0.28 / 0.29, abs=1e-3)
    (tmp_path / "points/a/sommerfeld_hist.csv").write_text(
        "s_low,s_high,count,fraction\n0,1e-10,0,0\n")
    with pytest.raises(ValueError, match="not the s = 0 bin"):
        contact_states.rows(tmp_path)


def test_the_ramp_table_is_what_the_docs_check_reads(tmp_path):
    """dilatant.plots.ramp_table: one row per done point, its marker keyed on
    seed, mu0 and lambda; a jammed point has no eta."""
    from dilatant.plots import ramp_table
    (tmp_path / "flowcurves.csv").write_text(
        "cell.seed,mu0,lambda,status,shear_stress,gamma_dot,eta,eta_err,frac_bl,"
        "inertial_number,frac_steps_unconverged,jammed\n"
        "1,0.4,100,done,10000,5.3247,1878.01,45.6,0.4799,0.0286,0,false\n"
        "1,0.4,316,done,99856,1e-6,,,0.9,0.001,0.02,true\n"
        "1,0.4,1000,skipped,,,,,,,,\n")
    lines = ramp_table.table(tmp_path).splitlines()
    assert "key=cell.seed,mu0,lambda" in lines[0]
    assert lines[4] == "| 1 | 0.4 | 100 | 1e4 | 5.32 | 1,878 ± 46 | 0.480 | 0.0286 | 0 |"
    assert lines[5] == "| 1 | 0.4 | 316 | 9.99e4 | 1e-6 | – (jammed) | 0.900 | 0.001 | 2 |"
    assert len(lines) == 6


def test_the_ramp_table_marks_a_point_that_is_not_steady(tmp_path):
    """A point run to the end of its strain while its rate still drifted
    (sweep.extend_unsteady_to) keeps its row, and says it is no steady point;
    a steady point that is not valid (contacts beyond s_lim) says that."""
    from dilatant.plots import ramp_table
    (tmp_path / "flowcurves.csv").write_text(
        "cell.seed,mu0,lambda,status,shear_stress,gamma_dot,eta,eta_err,frac_bl,"
        "inertial_number,frac_steps_unconverged,jammed,valid,steady\n"
        "1,0.4,68.13,done,4642,4.78,971.0,21,0.384,0.0376,0,false,true,true\n"
        "1,0.4,146.8,done,21550,1.74,12358,3226,0.702,0.0064,0.0001,false,false,false\n"
        "1,0.4,215.4,done,46397,1.0,46397,900,0.75,0.003,0,false,false,true\n")
    lines = ramp_table.table(tmp_path).splitlines()
    assert lines[4].endswith("| 971.0 ± 21 | 0.384 | 0.0376 | 0 |")
    assert "| 12,360 ± 3,200 (not steady) |" in lines[5]
    assert "| 46,400 ± 900 (not valid) |" in lines[6]
