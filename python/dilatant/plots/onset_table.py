"""Onsets of thickening measured on a sweep's flow curves, as the table
`dilatant predict` compiles in (data/jamming/onsets.csv, docs/jamming.md
"The onset scale").

    dilatant analyze SWEEP/flowcurves.csv --out AN --no-plots
    PYTHONPATH=python python3 -m dilatant.plots.onset_table SWEEP/flowcurves.csv AN/curves.csv \\
        MODEL SOURCE >> onsets.csv

For every curve of AN/curves.csv with an onset (eta above 1.1 x its Newtonian
plateau: docs/analysis.md), the inertial number at the onset is interpolated
in log-log between the curve's two points around the onset rate, from the
points' own `inertial_number`; phi_bulk is the mean over the curve's points.
Rates are in eta_f/(rho_p R^2), stresses in eta_f^2/(rho_p R^2) (the sweep's
units). --header prints the header line first.
"""
import csv
import math
import sys

HEADER = ("mu0,phi_bulk,s_c,onset_rate,onset_stress,inertial_number,eta_newtonian,"
          "seed,model,source")


def sample_keys(label):
    """'mu0=0.1 seed=1' -> {'mu0': '0.1', 'seed': '1'}."""
    return dict(part.split("=", 1) for part in label.split() if "=" in part)


def matches(row, keys):
    for key, value in keys.items():
        column = {"seed": "cell.seed"}.get(key, key)
        if column not in row or float(row[column]) != float(value):
            return False
    return True


def interpolate_log(x, xs, ys):
    for k in range(1, len(xs)):
        if xs[k - 1] <= x <= xs[k]:
            w = (math.log(x) - math.log(xs[k - 1])) / (math.log(xs[k]) - math.log(xs[k - 1]))
            return math.exp((1 - w) * math.log(ys[k - 1]) + w * math.log(ys[k]))
    raise ValueError(f"onset rate {x} outside the curve's rates {xs[0]}..{xs[-1]}")


def main(argv):
    args = [a for a in argv[1:] if a != "--header"]
    if len(args) != 4:
        sys.exit(__doc__)
    flow_file, curves_file, model, source = args
    rows = [r for r in csv.DictReader(open(flow_file)) if r["status"] == "done"
            and r["jammed"] == "false" and r["gamma_dot"]]
    if "--header" in argv:
        print(HEADER)
    for curve in csv.DictReader(open(curves_file)):
        if not curve["onset_rate"]:
            continue
        keys = sample_keys(curve["sample"])
        points = sorted((r for r in rows if matches(r, keys)), key=lambda r: float(r["gamma_dot"]))
        rates = [float(r["gamma_dot"]) for r in points]
        inertial = [float(r["inertial_number"]) for r in points]
        onset_rate = float(curve["onset_rate"])
        phi_bulk = sum(float(r["phi_bulk"]) for r in points) / len(points)
        print(f"{keys.get('mu0', points[0]['mu0'])},{phi_bulk:.4f},{points[0]['s_c']},"
              f"{onset_rate:.4g},{float(curve['onset_stress']):.4g},"
              f"{interpolate_log(onset_rate, rates, inertial):.4g},"
              f"{float(curve['eta_newtonian']):.4g},{keys.get('seed', points[0].get('cell.seed', ''))},"
              f"{model},{source}")


if __name__ == "__main__":
    main(sys.argv)
