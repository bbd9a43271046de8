"""The sweep figures' caption names the versions that made what they show: the
runs' (several when a sweep was resumed by another binary) and the analysis's,
whose regimes the figures label, when it differs."""
import json

from dilatant.plots import sweep


def rows(*versions):
    return [{"version": v, "dir": "points/missing"} for v in versions]


def test_one_version_is_named_once(tmp_path):
    (tmp_path / "analysis").mkdir()
    (tmp_path / "analysis" / "fits.json").write_text(json.dumps({"version": "0.8.0"}))
    text = sweep.settings_caption(tmp_path, rows("0.8.0", "0.8.0"), ["fluid.lambda"])
    assert text.startswith("dilatant 0.8.0; swept: fluid.lambda")


def test_a_later_analysis_and_mixed_runs_are_named(tmp_path):
    (tmp_path / "analysis").mkdir()
    (tmp_path / "analysis" / "fits.json").write_text(json.dumps({"version": "0.12.0"}))
    text = sweep.settings_caption(tmp_path, rows("0.8.0"), [])
    assert text.startswith("dilatant 0.8.0 (regimes: analysis by 0.12.0)")
    mixed = sweep.settings_caption(tmp_path, rows("0.8.0", "0.12.0", "0.8.0"), [])
    assert mixed.startswith("dilatant 0.12.0+0.8.0 (regimes: analysis by 0.12.0)")


def test_no_analysis_names_the_runs_only(tmp_path):
    assert sweep.settings_caption(tmp_path, rows("0.5.0"), []) == "dilatant 0.5.0; swept: nothing"
