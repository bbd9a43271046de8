"""How a sweep's contacts are held, point by point: the share that stick (no
sliding, so Sommerfeld number s = 0; in the literal model a sticking contact is
boundary-lubricated and carries mu0, at any stress), beside the share that is
boundary-lubricated at all (`frac_bl`) and the macroscopic friction `mu_eff`.
It measures why the decisive study's Newtonian branch depends on mu0
(docs/paper-reproduction.md "The decisive study").

    PYTHONPATH=python python3 -m dilatant.plots.contact_states SWEEP_DIR > contact_states.csv

Reads SWEEP_DIR/flowcurves.csv and each finished point's sommerfeld_hist.csv,
whose first row (s_low = s_high = 0) counts the sticking contacts over the
measured part of the run, as frac_bl does. `stick_share_of_bl` is frac_stick /
frac_bl. Standard library only.
"""
import sys
from pathlib import Path

from .table_rows import number, read_rows

HEADER = ("sample,phi,mu0,lambda,shear_stress,eta,frac_bl,frac_stick,stick_share_of_bl,"
          "mu_eff,pressure,version,dir")


def sticking_fraction(hist_file):
    """The first row of a sommerfeld_hist.csv: the contacts at s = 0."""
    first = read_rows(hist_file)[0]
    if number(first["s_low"]) != 0 or number(first["s_high"]) != 0:
        raise ValueError(f"{hist_file}: its first row is not the s = 0 bin")
    return number(first["fraction"])


def rows(folder):
    folder = Path(folder)
    out = []
    for r in read_rows(folder / "flowcurves.csv"):
        hist = folder / r["dir"] / "sommerfeld_hist.csv"
        if r["status"] != "done" or r["jammed"] == "true" or not hist.exists():
            continue
        stick, bl = sticking_fraction(hist), number(r["frac_bl"])
        fields = [r["sample"], r["phi"], r["mu0"], r["lambda"], r["shear_stress"], r["eta"],
                  r["frac_bl"], f"{stick:.4g}", f"{stick / bl:.3g}" if bl > 0 else "",
                  r["mu_eff"], r["pressure"], r["version"], r["dir"]]
        out.append(",".join(f'"{f}"' if "," in f else f for f in fields))
    return out


def main(argv):
    if len(argv) != 2:
        sys.exit(__doc__)
    print(HEADER)
    for line in rows(argv[1]):
        print(line)


if __name__ == "__main__":
    main(sys.argv)
