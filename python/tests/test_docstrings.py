"""The examples of the module's docstrings (help(dilatant), help(dilatant.cell))
run as written, each on a tiny cell in seconds: an example a user copies works."""
import doctest

import pytest

import dilatant
import dilatant.cell
import dilatant.scene


@pytest.mark.parametrize("module", [dilatant, dilatant.cell, dilatant.scene],
                         ids=lambda m: m.__name__)
def test_the_docstring_examples_run(module, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)  # whatever an example writes stays in tmp_path
    result = doctest.testmod(module, optionflags=doctest.ELLIPSIS | doctest.NORMALIZE_WHITESPACE,
                             verbose=False)
    assert result.attempted > 0
    assert result.failed == 0
