"""A refinement's figures (sweep.refines, docs/sweeps.md "Refining a ramp") draw
each of its curves with the finished points of the ramp it refines: the rows of
both tables, each extra point on the curve of the ramp point its segment started
from, the ramp's rows with their run folders made absolute, and none of the
ramp's other curves or unfinished points."""
from dilatant.plots.table_rows import read_rows, refined_ramp_rows

COLUMNS = "fluid.lambda,point,status,phi,sample,start,dir"


def write(folder, rows, sweep):
    folder.mkdir(parents=True)
    (folder / "sweep.toml").write_text(sweep)
    (folder / "flowcurves.csv").write_text(COLUMNS + "\n" + "\n".join(rows) + "\n")


def test_a_refinements_curves_take_in_their_ramps_finished_points(tmp_path):
    ramp = tmp_path / "ramp"
    write(ramp, ["1,0,done,0.61,mu0=0.1 seed=1,cold,points/0-a",
                 "10,1,done,0.61,mu0=0.1 seed=1,points/0-a,points/1-a",
                 "100,2,pending,0.61,mu0=0.1 seed=1,points/1-a,points/2-a",
                 "1,3,done,0.61,mu0=0.4 seed=1,cold,points/3-b"], "[sweep]\ncontinuation = true\n")
    refine = tmp_path / "refine"
    # A segment of two extra points (its table labels them without the seed,
    # which it does not sweep): 2 from the ramp's 1, 5 from 2.
    write(refine, ["2,0,done,0.61,mu0=0.1,../ramp/points/0-a,points/0-c",
                   "5,1,done,0.61,mu0=0.1,points/0-c,points/1-c"],
          f"[sweep]\ncontinuation = true\nrefines = '{ramp}'\n")
    rows = refined_ramp_rows(refine, read_rows(refine / "flowcurves.csv"))
    assert [(r["fluid.lambda"], r["sample"], r["dir"]) for r in rows] == [
        ("2", "mu0=0.1 seed=1", "points/0-c"), ("5", "mu0=0.1 seed=1", "points/1-c"),
        ("1", "mu0=0.1 seed=1", str(ramp / "points/0-a")),
        ("10", "mu0=0.1 seed=1", str(ramp / "points/1-a"))]
    # A sweep that refines nothing is read as it is.
    plain = read_rows(ramp / "flowcurves.csv")
    assert refined_ramp_rows(ramp, plain) is plain
