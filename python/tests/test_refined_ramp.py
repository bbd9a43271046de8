"""A refinement's figures (sweep.refines, docs/sweeps.md "Refining a ramp") draw
each of its curves with the finished points of the ramp it refines: the rows of
both tables, the ramp's with their run folders made absolute, and none of the
ramp's other curves or unfinished points."""
from dilatant.plots.table_rows import read_rows, refined_ramp_rows

COLUMNS = "fluid.lambda,point,status,phi,sample,dir"


def write(folder, rows, sweep):
    folder.mkdir(parents=True)
    (folder / "sweep.toml").write_text(sweep)
    (folder / "flowcurves.csv").write_text(COLUMNS + "\n" + "\n".join(rows) + "\n")


def test_a_refinements_curves_take_in_their_ramps_finished_points(tmp_path):
    ramp = tmp_path / "ramp"
    write(ramp, ["1,0,done,0.61,mu0=0.1,points/0-a", "10,1,done,0.61,mu0=0.1,points/1-a",
                 "100,2,pending,0.61,mu0=0.1,points/2-a",
                 "1,3,done,0.61,mu0=0.4,points/3-b"], "[sweep]\ncontinuation = true\n")
    refine = tmp_path / "refine"
    write(refine, ["3,0,done,0.61,mu0=0.1,points/0-c"],
          f"[sweep]\ncontinuation = true\nrefines = '{ramp}'\n")
    rows = refined_ramp_rows(refine, read_rows(refine / "flowcurves.csv"))
    assert [(r["fluid.lambda"], r["dir"]) for r in rows] == [
        ("3", "points/0-c"), ("1", str(ramp / "points/0-a")), ("10", str(ramp / "points/1-a"))]
    # A sweep that refines nothing is read as it is.
    plain = read_rows(ramp / "flowcurves.csv")
    assert refined_ramp_rows(ramp, plain) == plain
