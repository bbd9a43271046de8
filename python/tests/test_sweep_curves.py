"""A sweep's curves as its figures read them (dilatant.plots.sweep_curves):
each curve takes its regime and its contact onset (docs/analysis.md rule 8)
from the analysis's curves.csv, and a curves.csv from before 0.15, without
the contact onset, leaves it NaN."""
import csv
import io
import math
import shutil
from pathlib import Path

from dilatant.plots import sweep_curves

DOCS = Path(__file__).resolve().parents[2] / "docs" / "paper-reproduction"


def test_the_contact_onset_comes_from_the_analysis(tmp_path):
    # A committed sweep table and its analysis (decisive-le-mu0: mu0 0.3 and
    # 0.35, two seeds each, every curve with a contact onset).
    shutil.copy(DOCS / "decisive-le-mu0" / "flowcurves.csv", tmp_path / "flowcurves.csv")
    (tmp_path / "analysis").mkdir()
    analysis = (DOCS / "decisive-le-mu0" / "curves.csv").read_text()
    (tmp_path / "analysis" / "curves.csv").write_text(analysis)
    _, curves = sweep_curves.load_curves(tmp_path)
    assert len(curves) == 4
    expected = {row["sample"]: row for row in csv.DictReader(io.StringIO(analysis))}
    for c in curves:
        row = expected[c.sample]
        assert c.regime == row["regime"]
        assert c.contact_onset_rate == float(row["contact_onset_rate"]) > 0


def test_an_analysis_without_the_contact_onset_leaves_it_nan(tmp_path):
    shutil.copy(DOCS / "decisive-le-mu0" / "flowcurves.csv", tmp_path / "flowcurves.csv")
    (tmp_path / "analysis").mkdir()
    (tmp_path / "analysis" / "curves.csv").write_text(
        "sample,phi,regime,n,bagnold\nmu0=0.3 seed=1,0.61,dst,,\n")
    _, curves = sweep_curves.load_curves(tmp_path)
    first = next(c for c in curves if c.sample == "mu0=0.3 seed=1")
    assert first.regime == "dst" and math.isnan(first.contact_onset_rate)
