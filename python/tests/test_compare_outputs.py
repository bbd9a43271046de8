"""scripts/compare_outputs.py: equal files compare equal whatever the names of
their folders (a checkpoint's bytes may hold a short folder name such as v1),
and a difference of the last bits of a number is round-off, not identity."""
import subprocess
import sys

from conftest import SOURCE_DIR

SCRIPT = SOURCE_DIR / "scripts" / "compare_outputs.py"


def compare(old, new, *flags, cwd=None):
    return subprocess.run([sys.executable, str(SCRIPT), str(old), str(new), *flags],
                          capture_output=True, text=True, cwd=cwd)


def test_equal_binary_files_are_identical_whatever_the_folders(tmp_path):
    state = bytes(range(256)) + b"v1 and v0 inside the state's doubles" + bytes(range(255, -1, -1))
    for name in ("v0", "v1"):
        (tmp_path / name).mkdir()
        (tmp_path / name / "checkpoint.bin").write_bytes(state)
    result = compare("v0", "v1", cwd=tmp_path)  # as typed in the folder: short names
    assert result.returncode == 0, result.stdout
    assert "1 files compared, 0 differ" in result.stdout


def test_a_changed_byte_and_round_off_are_told_apart(tmp_path):
    for name, value in (("old", "1.0000000000000002"), ("new", "1.0")):
        (tmp_path / name).mkdir()
        (tmp_path / name / "timeseries.csv").write_text(f"t,x\n0.5,{value}\n")
    result = compare(tmp_path / "old", tmp_path / "new")
    assert result.returncode == 3 and "round-off only" in result.stdout, result.stdout
    (tmp_path / "new" / "timeseries.csv").write_text("t,x\n0.5,1.01\n")
    result = compare(tmp_path / "old", tmp_path / "new")
    assert result.returncode == 1, result.stdout


def test_the_folder_lock_is_no_result(tmp_path):
    """A newer version leaves an empty .dilatant.lock in its folders (since
    0.13.1); an older one none. That is no difference in the results."""
    for name in ("old", "new"):
        (tmp_path / name).mkdir()
        (tmp_path / name / "summary.json").write_text('{"eta": 1.0}\n')
    (tmp_path / "new" / ".dilatant.lock").write_text("")
    result = compare(tmp_path / "old", tmp_path / "new")
    assert result.returncode == 0, result.stdout
    assert "1 files compared, 0 differ" in result.stdout
