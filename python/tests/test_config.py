"""Configurations: a dict, TOML text and a file give the same Config, and the
resolved config goes round trip (dict -> Config -> dict -> Config)."""
import copy
import warnings

import pytest

import dilatant
from conftest import TINY, TINY_TOML


def test_dict_text_and_file_agree(tiny_file):
    from_dict = dilatant.load_config(TINY)
    from_text = dilatant.load_config(TINY_TOML)
    from_file = dilatant.load_config(tiny_file)
    assert from_dict.to_dict() == from_text.to_dict() == from_file.to_dict()
    assert from_dict.mode == "cell"
    assert from_file.source == str(tiny_file)


def test_round_trip_of_the_resolved_config():
    config = dilatant.load_config(TINY, overrides={"friction.mu0": 0.3})
    resolved = config.to_dict()
    again = dilatant.load_config(copy.deepcopy(resolved))
    assert again.to_dict() == resolved
    assert dilatant.load_config(config.to_toml()).to_dict() == resolved
    assert resolved["friction"]["mu0"] == 0.3
    assert resolved["cell"]["size"] == [6.0, 5.0, 7.0]


def test_defaults_are_filled_in():
    resolved = dilatant.load_config(TINY).to_dict()
    default = dilatant.load_config().to_dict()
    assert resolved["friction"] == default["friction"]
    assert default["cell"]["size"] == [25.0, 10.0, 27.0]


def test_overrides_as_list_and_dict_agree():
    a = dilatant.load_config(TINY, ["friction.mu0=0.2", "friction.law=coulomb"])
    b = dilatant.load_config(TINY, {"friction.mu0": 0.2, "friction.law": "coulomb"})
    assert a.to_dict() == b.to_dict()
    assert a.to_dict()["friction"]["law"] == "coulomb"


def test_numpy_values_are_accepted():
    np = pytest.importorskip("numpy")
    config = {"cell": {"size": np.array([6.0, 5.0, 7.0]), "seed": np.int64(3)}}
    resolved = dilatant.load_config(config).to_dict()
    assert resolved["cell"]["size"] == [6.0, 5.0, 7.0]
    assert resolved["cell"]["seed"] == 3


def test_the_critical_load_law_from_python():
    """friction.critical_load is a force in eta_f^2/rho_p (docs/model.md "Friction"):
    the run reports it, in code units (F* / lambda^2 here) and as the onset stress."""
    config = dilatant.load_config(TINY, {"friction.law": "critical_load",
                                         "friction.critical_load": 50.0, "fluid.lambda": 5.0})
    friction = config.to_dict()["friction"]
    assert friction["law"] == "critical_load" and friction["critical_load"] == 50.0
    with warnings.catch_warnings():  # a tiny cell's 0.05 strain: its validity is not the point
        warnings.simplefilter("ignore", RuntimeWarning)
        summary = dilatant.run(config).summary
    assert summary["friction_law"] == "critical_load"
    assert summary["critical_load_code"] == pytest.approx(50.0 / 25.0, rel=1e-15)
    assert summary["onset_stress"] == pytest.approx(50.0, rel=1e-15)
    assert summary["lambda_at_onset_stress"] == pytest.approx(50.0 ** 0.5, rel=1e-15)
    with pytest.raises(dilatant.ConfigError, match="needs friction.critical_load > 0"):
        dilatant.load_config(TINY, {"friction.law": "critical_load"})
