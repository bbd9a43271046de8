"""docs/jamming/predictor_checks.csv says what each flow curve did (`observed`)
as docs/jamming.md's record counts it: a jam only counts as one when its cold
start jams too, and a curve that never jams is DST when the analysis beside its
table says so (under imposed stress its rate fell). The analysis is matched to
a curve by sample and nominal phi, since one sample label may hold several phi."""
from dilatant.plots import predictor_checks


def test_observed_reads_the_cold_start_and_the_analysis():
    assert predictor_checks.observed(1000.0, "jammed", "") == "jams"
    assert predictor_checks.observed(100.0, "flowed", "dst jammed") == "jams in the ramp only"
    assert predictor_checks.observed(3000.0, "", "") == "jams without a cold start"
    assert predictor_checks.observed(None, "", "dst rate_falls") == "dst without a jam"
    assert predictor_checks.observed(None, "", "dst n_above_cap") == "dst without a jam"
    assert predictor_checks.observed(None, "", "cst") == "flows"
    assert predictor_checks.observed(None, "", "unresolved") == "flows"
    assert predictor_checks.observed(None, "", "") == "flows"


def test_analysis_is_keyed_by_sample_and_phi(tmp_path):
    flow = tmp_path / "flowcurves.csv"
    flow.write_text("sample,phi\n")
    (tmp_path / "curves.csv").write_text(
        "sample,phi,regime,dst_evidence\n"
        "mu0=0.6,0.58,cst,\n"
        "mu0=0.6,0.59,dst,jammed\n"
        "mu0=0.4 seed=2,0.61,dst,rate_falls\n")
    regimes = predictor_checks.analysed(flow)
    assert regimes[("mu0=0.6", 0.58)] == "cst"
    assert regimes[("mu0=0.6", 0.59)] == "dst jammed"
    assert regimes[("mu0=0.4 seed=2", 0.61)] == "dst rate_falls"


def test_a_table_without_an_analysis_gives_none(tmp_path):
    flow = tmp_path / "flowcurves.csv"
    flow.write_text("sample,phi\n")
    assert predictor_checks.analysed(flow) == {}
