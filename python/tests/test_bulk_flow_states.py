"""The bulk flow states `dilatant predict` compiles in (data/jamming/bulk_flow_states.csv)
are what dilatant.plots.bulk_flow_states makes from the committed flow curves, and
the script classifies a ramp as the table's README says: cst, dst only with a
confirming cold start or a fall the analysis places (then also a ramp still
running above it), jammed at its first stress; curves outside the Lees–Edwards
box are left out; curves that contradict each other stop it."""
import pytest

from conftest import SOURCE_DIR
from dilatant.plots import bulk_flow_states

SWEEP = """[cell]
size = [12.0, 8.0, 14.0]
seed = 1
boundary = 'lees-edwards'
control = 'stress'
[friction]
law = 'stribeck'
[fluid]
lubrication = 'none'
drag = 'none'
"""
COLUMNS = ("sample,phi,mu0,lambda,status,jammed,valid,phi_bulk,frac_steps_unconverged,version,"
           "jam_cold_start,shear_stress")


def write_sweep(folder, rows, sweep=SWEEP):
    """rows without the last column, shear_stress: it is lambda^2 (paper units)."""
    def with_stress(row):
        lam = row.split(",")[3]
        return f"{row},{float(lam) ** 2:g}" if row.split(",")[4] == "done" else row + ","
    folder.mkdir(parents=True)
    (folder / "sweep.toml").write_text(sweep)
    (folder / "flowcurves.csv").write_text(
        COLUMNS + "\n" + "\n".join(with_stress(r) for r in rows) + "\n")


def test_the_committed_table_is_the_scripts_output(monkeypatch, capsys):
    monkeypatch.chdir(SOURCE_DIR)
    bulk_flow_states.main(["bulk_flow_states", "docs/paper-reproduction"])
    made = capsys.readouterr().out
    assert made == (SOURCE_DIR / "data/jamming/bulk_flow_states.csv").read_text()


def test_ramps_are_classified_and_other_cells_left_out(tmp_path, monkeypatch, capsys):
    monkeypatch.chdir(tmp_path)
    write_sweep(tmp_path / "le", [
        "A,0.6,1,10,done,false,true,0.60,0,0.8.0,",
        "A,0.6,1,100,done,true,true,0.60,0,0.8.0,jammed",   # dst, confirmed
        "B,0.61,1,10,done,false,true,0.61,0,0.8.0,",
        "B,0.61,1,100,done,true,true,0.61,0,0.8.0,",        # a jam no cold start confirms
        "C,0.62,1,1,done,true,true,0.62,0,0.8.0,",          # jammed at its first stress
        "D,0.55,1,1,done,false,true,0.55,0.1,0.8.0,",
        "D,0.55,1,10,done,false,false,0.55,0.2,0.8.0,",     # cst, valid to lambda 1
        "F,0.61,0.1,0.1,done,false,true,0.61,0,0.8.0,",
        "F,0.61,0.1,1,pending,,,,,,",                       # a ramp still running
        "G,0.62,0.1,0.1,done,false,true,0.62,0,0.8.0,",
        "G,0.62,0.1,1,failed,,,,,,",                        # a ramp whose chain broke
        "S,0.6,0.4,10,done,false,true,0.60,0,0.8.0,",
        "S,0.6,0.4,100,done,false,true,0.60,0.3,0.8.0,",     # its rate fell here
        "S,0.6,0.4,1000,done,false,false,0.60,0.3,0.8.0,",   # and flows on
        "R,0.6,0.3,10,done,false,true,0.60,0,0.8.0,",
        "R,0.6,0.3,100,done,false,true,0.60,0,0.8.0,",       # its rate stopped growing
        "P,0.61,0.4,10,done,false,true,0.61,0,0.8.0,",
        "P,0.61,0.4,100,done,false,true,0.61,0,0.8.0,",      # its rate fell here
        "P,0.61,0.4,1000,pending,,,,,,",                     # still running above the fall
        "Q,0.62,0.4,10,done,false,true,0.62,0,0.8.0,",
        "Q,0.62,0.4,100,done,false,true,0.62,0,0.8.0,",
        "Q,0.62,0.4,1000,pending,,,,,,"])                    # dst, but no fall placed
    (tmp_path / "le" / "curves.csv").write_text(
        "sample,phi,regime,dst_evidence,fall_stress\nD,0.55,cst,,\nS,0.6,dst,rate_falls,10000\n"
        "R,0.6,dst,n_above_cap,\nP,0.61,dst,rate_falls,10000\nQ,0.62,dst,n_above_cap,\n")
    # An analysis older than fall_stress: its rate_falls ramp cannot be placed.
    write_sweep(tmp_path / "old", ["T,0.6,0.3,10,done,false,true,0.60,0,0.8.0,",
                                   "T,0.6,0.3,100,done,false,true,0.60,0,0.8.0,"])
    (tmp_path / "old" / "curves.csv").write_text(
        "sample,phi,regime,dst_evidence\nT,0.6,dst,rate_falls\n")
    write_sweep(tmp_path / "walls", ["E,0.58,1,1,done,false,true,0.58,0,0.8.0,"],
                SWEEP.replace("'lees-edwards'", "'walls'"))
    write_sweep(tmp_path / "refine", ["H,0.6,1,20,done,true,true,0.60,0,0.8.0,jammed"],
                "[sweep]\nrefines = '/runs/le'\n" + SWEEP)
    bulk_flow_states.main(["bulk_flow_states", "le", "walls", "refine", "old"])
    out = capsys.readouterr()
    rows = out.out.splitlines()
    assert rows[0] == bulk_flow_states.HEADER
    # regime, max_lambda, max_valid_lambda, jam_lambda, dst_evidence, fall_lambda
    assert {r.split(",")[12]: r.split(",")[2:6] + r.split(",")[13:] for r in rows[1:]} == {
        "A": ["dst", "10", "10", "100", "jammed", ""], "C": ["jammed", "", "", "1", "", ""],
        "D": ["cst", "10", "1", "", "", ""], "S": ["dst", "1000", "100", "", "rate_falls", "100"],
        "R": ["dst", "100", "100", "", "n_above_cap", ""],
        "P": ["dst", "100", "100", "", "rate_falls", "100"]}
    # P counts up to its last done point, and stderr says it is not finished.
    assert ("le/flowcurves.csv P: counted though not finished: dst by rate_falls, its rate fell "
            "at lambda 100; 1 points above still pending or failed") in out.err
    assert "left out: le/flowcurves.csv P" not in out.err  # counted, so not "left out"
    assert "left out: le/flowcurves.csv Q: the ramp is not finished (1 points pending or failed)" \
        in out.err
    assert "le/flowcurves.csv B: jammed at lambda 100 without a cold start" in out.err
    assert "walls/flowcurves.csv E: cell.boundary = walls" in out.err
    assert "le/flowcurves.csv F: the ramp is not finished (1 points pending or failed)" in out.err
    assert "le/flowcurves.csv G: the ramp is not finished" in out.err
    assert "refine/flowcurves.csv: a refinement of the ramps in /runs/le" in out.err
    assert ("old/flowcurves.csv T: dst by rate_falls in an analysis without fall_stress"
            in out.err)


def test_contradicting_curves_stop_the_script(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    write_sweep(tmp_path / "le", ["A,0.6,1,1,done,true,true,0.57,0,0.8.0,",
                                  "B,0.6,1,1,done,false,true,0.58,0,0.8.0,"])
    with pytest.raises(SystemExit, match="contradict"):
        bulk_flow_states.main(["bulk_flow_states", "le"])
