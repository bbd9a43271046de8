"""The decisive study's Fig. 2 draws every folder's curves in one figure: a
curve found in two folders (the first mu0 0.4 run at the cap of 1000 and its
converged rerun) is drawn from each and labelled with folder and cap; regimes
come from each folder's analysis."""
import pytest

from dilatant.plots import decisive_fig2
from dilatant.plots.common import NothingToPlot

COLUMNS = ("sample,phi,mu0,lambda,status,jammed,valid,gamma_dot,eta,eta_err,shear_stress,"
           "version,dir")


def folder(docs, name, cap, rows, regimes=""):
    (docs / name).mkdir(parents=True)
    solver = "" if cap is None else f"[solver]\nmax_iterations = {cap}\n"
    (docs / name / "sweep.toml").write_text("[cell]\nphi = 0.61\n" + solver)
    (docs / name / "flowcurves.csv").write_text(COLUMNS + "\n" + "\n".join(rows) + "\n")
    if regimes:
        (docs / name / "curves.csv").write_text("sample,phi,regime,n,bagnold\n" + regimes)


def test_every_folder_is_drawn_and_a_repeated_curve_names_its_source(tmp_path):
    folder(tmp_path, "le", None, [
        "mu0=0.1 seed=1,0.61,0.1,1,done,false,true,0.02,55,2,1,0.8.0,points/a",
        "mu0=0.1 seed=1,0.61,0.1,10,done,false,true,0.8,127,3,100,0.8.0,points/b",
        "mu0=0.4 seed=1,0.61,0.4,1,done,false,true,0.01,99,4,1,0.8.0,points/c",
        "mu0=0.4 seed=1,0.61,0.4,10,pending,,,,,,,,points/d"],
        "mu0=0.1 seed=1,0.61,cst,1.5,false\n")
    folder(tmp_path, "rerun", 10000, [
        "mu0=0.4 seed=1,0.61,0.4,1,done,false,true,0.011,95,4,1,0.8.0,points/a",
        "mu0=0.4 seed=2,0.61,0.4,1,done,false,true,0.012,90,4,1,0.8.0,points/b"])
    labels = decisive_fig2.draw(tmp_path, ["le", "rerun", "not-run"])
    assert (tmp_path / "decisive-fig2.png").is_file()
    assert (tmp_path / "decisive-fig2.svg").is_file()
    assert labels == [
        r"$\mu_0$ = 0.1 (seed=1), $\phi$ = 0.61: cst, n = 1.50",
        r"$\mu_0$ = 0.4 (seed=1), $\phi$ = 0.61 [le, cap 1000]",
        r"$\mu_0$ = 0.4 (seed=1), $\phi$ = 0.61 [rerun, cap 10000]",
        r"$\mu_0$ = 0.4 (seed=2), $\phi$ = 0.61"]


def test_the_wall_cell_beside_the_box_is_told_apart_by_folder(tmp_path):
    # The same sample at another nominal phi (the wall cell's 0.615) is the
    # same ramp in another cell: drawn from each folder, each label naming it.
    folder(tmp_path, "le", None, [
        "mu0=0.1 seed=1,0.61,0.1,1,done,false,true,0.02,55,2,1,0.8.0,points/a"])
    folder(tmp_path, "walls", None, [
        "mu0=0.1 seed=1,0.615,0.1,1,done,false,true,0.016,62,3,1,0.13.1,points/a",
        "mu0=0.4 seed=1,0.615,0.4,1,done,false,true,0.01,103,6,1,0.13.1,points/b"])
    decisive_fig2.main(["decisive_fig2", str(tmp_path), "le", "walls", "--name", "walls-fig2"])
    assert (tmp_path / "walls-fig2.png").is_file()
    assert not (tmp_path / "decisive-fig2.png").exists()
    assert decisive_fig2.draw(tmp_path, ["le", "walls"], "again") == [
        r"$\mu_0$ = 0.1 (seed=1), $\phi$ = 0.61 [le, cap 1000]",
        r"$\mu_0$ = 0.1 (seed=1), $\phi$ = 0.615 [walls, cap 1000]",
        r"$\mu_0$ = 0.4 (seed=1), $\phi$ = 0.615"]


def test_nothing_finished_is_nothing_to_plot(tmp_path):
    with pytest.raises(NothingToPlot, match="no finished point"):
        decisive_fig2.draw(tmp_path, ["le"])
