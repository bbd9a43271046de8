"""A configuration dict as TOML text, in the dict's order.

Dicts reach the library as text, parsed by its one parser like a file, so
that a sweep's keys keep the order they were given in (the first varies
slowest, docs/sweeps.md) and every message names a key. Only what a
configuration holds: tables, arrays of tables ([[points]], [[scene.planes]]),
numbers, strings, booleans and arrays of them.
"""
import json
import math
import re

_BARE = re.compile(r"^[A-Za-z0-9_-]+$")


def _key(key):
    # "friction.mu0" in a [[points]] table is a dotted key, as in a file.
    parts = key.split(".")
    if all(_BARE.match(p) for p in parts):
        return key
    return json.dumps(key)


def _value(v, where):
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, int):
        return str(v)
    if isinstance(v, float):
        if math.isnan(v):
            return "nan"
        if math.isinf(v):
            return "inf" if v > 0 else "-inf"
        return repr(v)  # the shortest text that reads back exactly
    if isinstance(v, str):
        return json.dumps(v)  # a TOML basic string
    if isinstance(v, (list, tuple)):
        return "[" + ", ".join(_value(x, where) for x in v) + "]"
    if isinstance(v, dict):
        return "{" + ", ".join(f"{_key(k)} = {_value(x, where + '.' + k)}"
                               for k, x in v.items()) + "}"
    raise ValueError(f"{where}: cannot be a {type(v).__name__} (expected a number, string, "
                     "bool, list or dict)")


def _is_table_array(v):
    return isinstance(v, (list, tuple)) and len(v) > 0 and all(isinstance(x, dict) for x in v)


def _table(lines, path, table):
    scalars = [(k, v) for k, v in table.items()
               if not isinstance(v, dict) and not _is_table_array(v)]
    for k, v in scalars:
        lines.append(f"{_key(k)} = {_value(v, '.'.join(path + [k]))}")
    for k, v in table.items():
        if isinstance(v, dict):
            lines.append(f"[{'.'.join(_key(p) for p in path + [k])}]")
            _table(lines, path + [k], v)
        elif _is_table_array(v):
            for item in v:
                lines.append(f"[[{'.'.join(_key(p) for p in path + [k])}]]")
                _table(lines, path + [k], item)


def to_toml(config):
    """TOML text of a configuration dict; ValueError naming a key whose value
    TOML cannot hold."""
    lines = []
    for k in config:
        if not isinstance(k, str):
            raise ValueError(f"keys must be strings, got {type(k).__name__} {k!r}")
    _table(lines, [], config)
    return "\n".join(lines) + "\n"
