"""Bad input raises dilatant.ConfigError (a ValueError) with exactly the line
the CLI prints after "dilatant: error: "."""
import fcntl

import pytest

import dilatant
from conftest import TINY, TINY_TOML, run_cli

PREFIX = "dilatant: error: "


def cli_message(cli, *args):
    done = run_cli(cli, "run", *args, check=False)
    assert done.returncode == 2, done.stderr
    line = done.stderr.strip()
    assert line.startswith(PREFIX)
    return line[len(PREFIX):]


@pytest.mark.parametrize("text", [
    TINY_TOML + "[friction]\nmu0 = -0.1\n",
    TINY_TOML.replace("size =", "sizes ="),
    TINY_TOML + "[fluid]\neta_f = 1.0\n",
    TINY_TOML + "[solver]\nmax_iterations = \"many\"\n",
    TINY_TOML + "[friction]\nlaw = \"critical_load\"\n",
])
def test_file_errors_match_the_cli(cli, tmp_path, text):
    path = tmp_path / "bad.toml"
    path.write_text(text)
    expected = cli_message(cli, path, "--out", tmp_path / "out")
    with pytest.raises(dilatant.ConfigError) as error:
        dilatant.run(path)
    assert str(error.value) == expected
    with pytest.raises(dilatant.ConfigError) as error:
        dilatant.load_config(str(path))
    assert str(error.value) == expected


def test_override_errors_are_the_clis_named_as_overrides(cli, tiny_file, tmp_path):
    """The CLI's message, with its "--set key" named as Python's `overrides`."""
    expected = cli_message(cli, tiny_file, "--set", "friction.mu0=-1", "--out", tmp_path / "o")
    assert "--set friction.mu0" in expected
    for overrides in (["friction.mu0=-1"], {"friction.mu0": -1}):
        with pytest.raises(dilatant.ConfigError) as error:
            dilatant.run(tiny_file, overrides=overrides)
        assert str(error.value) == expected.replace("--set friction.mu0", "overrides friction.mu0")
    with pytest.raises(dilatant.ConfigError, match=r"^overrides frict\.mu0: unknown section"):
        dilatant.load_config(tiny_file, overrides={"frict.mu0": 0.3})
    with pytest.raises(dilatant.ConfigError, match=r"overrides fluid.lambda"):
        dilatant.sweeps.load_sweep({**TINY, "fluid": {"lambda": [1.0, 10.0]}},
                            overrides={"fluid.lambda": -1.0})


def test_config_error_is_a_value_error():
    assert issubclass(dilatant.ConfigError, ValueError)
    with pytest.raises(ValueError, match=r"^<dict>: friction.mu0 = -0.1: must be >= 0$"):
        dilatant.load_config({**TINY, "friction": {"mu0": -0.1}})


def test_unknown_key_in_a_dict_names_it():
    with pytest.raises(dilatant.ConfigError, match=r"^<dict>: cell.sizes: unknown key"):
        dilatant.load_config({"cell": {"sizes": [6.0, 5.0, 7.0]}})


def test_a_value_python_cannot_say_in_toml():
    with pytest.raises(dilatant.ConfigError, match=r"^<dict>: cell.size: cannot be a set"):
        dilatant.load_config({"cell": {"size": {6.0}}})


def test_missing_file():
    with pytest.raises(dilatant.ConfigError, match="nowhere.toml"):
        dilatant.run("nowhere.toml")


def test_wrong_argument_type():
    with pytest.raises(TypeError):
        dilatant.load_config(42)


def test_bad_analysis_and_prediction_input(tmp_path):
    with pytest.raises(dilatant.ConfigError, match=r"^phi 0.9: must be in \(0, 0.74\)$"):
        dilatant.predict(mu0=0.1, phi=0.9)
    with pytest.raises(dilatant.ConfigError, match=r"^onset_factor = 0.5: must be > 1$"):
        dilatant.analyze(tmp_path / "any.toml", onset_factor=0.5)
    bad = tmp_path / "curve.csv"
    bad.write_text("shear_rate,viscosity\n1,x\n")
    with pytest.raises(dilatant.ConfigError, match="curve.csv"):
        dilatant.analyze(bad)


def test_output_folder_errors_are_the_built_in_os_errors(cli, tiny_file, tmp_path):
    """A folder that cannot be used raises what os.makedirs would (issue 31,
    item 7), with the CLI's line (exit 2); once a RuntimeError."""
    blocker = tmp_path / "a-file"
    blocker.write_text("not a folder\n")
    expected = cli_message(cli, tiny_file, "--out", blocker)
    with pytest.raises(FileExistsError) as error:
        dilatant.run(tiny_file, out=blocker)
    assert expected in str(error.value)
    assert "cannot use as the output folder: a file is there" in str(error.value)
    with pytest.raises(NotADirectoryError, match="cannot create the output folder"):
        dilatant.run(tiny_file, out=blocker / "sub")
    with pytest.raises(FileExistsError):
        dilatant.phase_diagram(blocker, plots=False)
    assert issubclass(FileExistsError, OSError)


def test_a_folder_in_use_is_a_blocking_io_error(cli, tiny_file, tmp_path):
    """A folder whose lock another process holds (here this one, through its
    own open file: flock locks are per open file) is refused by the CLI (exit
    2) and by Python as BlockingIOError, with the same line; released, the run
    completes (docs/sweeps.md "One sweep per folder")."""
    out = tmp_path / "out"
    out.mkdir()
    with open(out / ".dilatant.lock", "w") as lock:
        fcntl.flock(lock, fcntl.LOCK_EX | fcntl.LOCK_NB)
        expected = cli_message(cli, tiny_file, "--out", out)
        assert expected.startswith(f"{out}: in use by another dilatant (")
        with pytest.raises(BlockingIOError) as error:
            dilatant.run(tiny_file, out=out)
        assert expected in str(error.value)
        assert not (out / "config.toml").exists()
    dilatant.run(tiny_file, out=out)
    assert (out / "summary.json").exists()
