"""The finished points of a ramp sweep as the markdown table of
docs/paper-reproduction.md "The decisive study", with the table-source marker
that scripts/check-docs-tables.py checks against the CSV:

    PYTHONPATH=python python3 -m dilatant.plots.ramp_table docs/paper-reproduction/decisive-le

Reads DIR/flowcurves.csv (its `done` points, in the table's order: seed, mu0,
lambda). eta in eta_f, stress in eta_f^2/(rho_p R^2), rate in eta_f/(rho_p R^2);
`I` the inertial number; a jammed point's eta reads "– (jammed)" (none in the CSV).
A point the sweep marked not steady (its wall speed still drifting at the end
of its run, `steady` false) or not valid (`valid` false: more than 5% of its
contacts beyond s_lim, or not steady) says so after its eta: its average is
in the table, but it is no point of a steady flow curve.
Standard library only.
"""
import math
import sys
from pathlib import Path

from .table_rows import number, read_rows

COLUMNS = ("cell.seed | mu0 | lambda | shear_stress | gamma_dot | eta eta_err | frac_bl | "
           "inertial_number | frac_steps_unconverged*100")
HEAD = ("| seed | mu0 | lambda | stress `tau` | `gamma_dot` | `eta` (`eta_f`) | `frac_bl` | "
        "inertial number `I` | steps unconverged (%) |")


def significant(x, digits):
    """x to `digits` significant digits, with thousands separators from 10^4."""
    if x == 0 or not math.isfinite(x):
        return f"{x:g}"
    decimals = digits - 1 - math.floor(math.log10(abs(x)))
    value = round(x, decimals)
    return f"{int(value):,}" if decimals <= 0 else f"{value:.{decimals}f}"


def short(x):
    """3 significant digits, exponent without padding: 9.99e6."""
    text = f"{x:.3g}"
    if "e" in text:
        mantissa, exponent = text.split("e")
        return f"{mantissa}e{int(exponent)}"
    return text


def table(folder):
    source = Path(folder) / "flowcurves.csv"
    lines = [f"<!-- table-source: {source.as_posix()} where=status=done "
             "key=cell.seed,mu0,lambda",
             f'     columns="{COLUMNS}" -->', HEAD, "|---" * 9 + "|"]
    for r in read_rows(source):
        if r["status"] != "done":
            continue
        jammed = r["jammed"] == "true"
        rate = short(number(r["gamma_dot"]))
        eta = ("– (jammed)" if jammed else
               f"{significant(number(r['eta']), 4)} ± {significant(number(r['eta_err']), 2)}")
        if not jammed and r.get("steady", "true") == "false":
            eta += " (not steady)"
        elif not jammed and r.get("valid", "true") == "false":
            eta += " (not valid)"
        lines.append(
            f"| {r['cell.seed']} | {r['mu0']} | {r['lambda']} | {short(number(r['shear_stress']))} "
            f"| {rate} | {eta} | {number(r['frac_bl']):.3f} | "
            f"{short(number(r['inertial_number']))} | "
            f"{number(r['frac_steps_unconverged']) * 100:.2g} |")
    return "\n".join(lines)


def main(argv):
    if len(argv) != 2:
        sys.exit(__doc__)
    print(table(argv[1]))


if __name__ == "__main__":
    main(sys.argv)
