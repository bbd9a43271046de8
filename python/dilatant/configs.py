"""Configurations given as a dict, TOML text or a file path, with overrides.

Every form goes through the library's one parser (io/config.hpp), so the
checks and messages are the CLI's: a file's errors name it and the line
("cell.toml:3: friction.mu0 = -0.1: must be >= 0"), a dict's "<dict>", a
text's "<text>".
"""
import json
import os
import re
import warnings
from pathlib import Path

from . import _core
from .toml_text import to_toml

DICT_SOURCE = "<dict>"


def plain(value):
    """numpy scalars and arrays, tuples and paths as plain Python values."""
    if isinstance(value, dict):
        return {str(k): plain(v) for k, v in value.items()}
    if isinstance(value, (list, tuple)):
        return [plain(v) for v in value]
    if isinstance(value, os.PathLike):
        return os.fspath(value)
    if hasattr(value, "tolist") and not isinstance(value, (str, bytes)):
        return plain(value.tolist())  # numpy arrays and scalars
    return value


def override_list(overrides):
    """`--set` strings from a list of "key=value" or a dict {"friction.mu0": 0.3}."""
    if overrides is None:
        return []
    if isinstance(overrides, dict):
        out = []
        for key, value in overrides.items():
            value = plain(value)
            text = ("true" if value else "false") if isinstance(value, bool) else json.dumps(value)
            out.append(f"{key}={text}")
        return out
    if isinstance(overrides, str):
        return [overrides]
    return [str(o) for o in overrides]


def kind(config):
    """'dict', 'path' or 'text'. A string is a path when it names a file or
    ends in .toml; otherwise it is TOML text."""
    if isinstance(config, dict):
        return "dict"
    if isinstance(config, os.PathLike):
        return "path"
    if isinstance(config, str):
        if "\n" not in config and (config.endswith(".toml") or os.path.isfile(config)):
            return "path"
        return "text"
    raise TypeError(f"a configuration is a dict, TOML text or a path, not {type(config).__name__}")


def from_dict(parse, config, sets):
    """parse(text, source, base_dir, overrides) of a dict, through its TOML text
    (toml_text.py). The text's line numbers mean nothing to the caller: a
    message names "<dict>: key" instead of "<dict>:LINE: key"."""
    try:
        text = to_toml(plain(config))
    except ValueError as e:
        raise _core.ConfigError(f"{DICT_SOURCE}: {e}") from None
    try:
        return parse(text, DICT_SOURCE, os.getcwd(), sets)
    except _core.ConfigError as e:
        message = re.sub(r"^<dict>:\d+(:\d+)?: ", DICT_SOURCE + ": ", str(e))
        raise _core.ConfigError(message) from None


def load_config(config=None, overrides=None):
    """The validated configuration (dilatant.Config) of a dict, TOML text or a
    path; None is the built-in default cell (`dilatant run` without CONFIG).
    `overrides` work as `--set`: ["friction.mu0=0.3"] or {"friction.mu0": 0.3}.
    Raises ConfigError with the CLI's message; each of the config's notes (an
    older resolved config.toml keeps the meaning its keys had) is issued as a
    UserWarning, as the CLI prints it."""
    loaded = _load(config, overrides)
    if loaded is config:  # already loaded, its notes already issued
        return loaded
    for note in loaded.notes:
        warnings.warn(note, UserWarning, stacklevel=2)
    return loaded


def overrides_named(call, *args):
    """call(*args), a ConfigError's "--set key" (the CLI's name for an override)
    renamed "overrides key": in Python the value came from `overrides=`."""
    try:
        return call(*args)
    except _core.ConfigError as e:
        message = re.sub(r"(^|[ (])--set ", r"\1overrides ", str(e))
        if message == str(e):
            raise
        raise _core.ConfigError(message) from None


def _load(config, overrides):
    return overrides_named(_load_with_sets, config, override_list(overrides))


def _load_with_sets(config, sets):
    if isinstance(config, _core.Config):
        if sets:
            return _core.config_from_text(config.to_toml(), config.source, os.getcwd(), sets)
        return config
    if config is None:
        return _core.default_config(sets)
    how = kind(config)
    if how == "dict":
        return from_dict(_core.config_from_text, config, sets)
    if how == "path":
        return _core.config_from_path(Path(config), sets)
    return _core.config_from_text(config, "<text>", os.getcwd(), sets)
