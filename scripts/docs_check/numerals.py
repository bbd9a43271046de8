"""Numbers as docs write them, and when a rounded one agrees with a file's."""
import math
import re

# A number as docs write it: 1,215 / -0.11 / +0.12 / 2.3e-4 / 4 x 10^4 / 10^4.
NUMBER = re.compile(
    r"(?<![\w.^])(?P<sign>[-+−]?)"
    r"(?:(?P<mant>\d{1,3}(?:,\d{3})+(?!\d)|\d+(?:\.\d+)?|\.\d+)(?P<exp>[eE][-+]?\d+)?"
    r"(?:\s*[x×]\s*10\^(?P<pow>[-+]?\d+))?"
    r"|10\^(?P<pow2>[-+]?\d+))(?![\w.])")
DASHES = ("—", "–")


def parse_numbers(text):
    """The numbers of a docs cell, each as (value, half of its last digit's unit)."""
    out = []
    for m in NUMBER.finditer(text):
        sign = -1.0 if m.group("sign") in ("-", "−") else 1.0
        if m.group("pow2") is not None:
            out.append((sign * 10.0 ** int(m.group("pow2")), 0.0))
            continue
        mant = m.group("mant").replace(",", "")
        exp = int(m.group("exp")[1:]) if m.group("exp") else 0
        if m.group("pow") is not None:
            exp += int(m.group("pow"))
        if "." in mant:
            digits = len(mant.split(".")[1])
            unit = 10.0 ** -digits
        else:
            stripped = mant.rstrip("0")
            trailing = len(mant) - len(stripped) if stripped else 0
            unit = 10.0 ** trailing
        value = sign * float(mant) * 10.0 ** exp
        out.append((value, 0.5 * unit * 10.0 ** exp))
    return out


def to_float(text):
    try:
        v = float(text)
    except (TypeError, ValueError):
        return None
    return v if math.isfinite(v) else None


def agrees(docs_value, half_unit, file_value):
    slack = 1e-9 * max(abs(docs_value), abs(file_value), 1e-300)
    return abs(docs_value - file_value) <= half_unit + slack


def show(v):
    return f"{v:.10g}"
