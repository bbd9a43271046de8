"""Where contacts leave the hydrodynamic branch, measured on sweeps' flow
curves: the table `dilatant predict` compiles in (data/jamming/onsets.csv,
docs/jamming.md "The onset scale").

    dilatant analyze SWEEP/flowcurves.csv --out AN --no-plots -q
    PYTHONPATH=python python3 -m dilatant.plots.onset_table [--header] MODEL \\
        SWEEP/flowcurves.csv AN/curves.csv [[--rerun] SWEEP2/flowcurves.csv AN2/curves.csv ...] \\
        > onsets.csv

The onset is `dilatant analyze`'s rule 8 (`contact_onset_stress` and
`contact_onset_rate` in curves.csv; docs/analysis.md): where frac_bl, having
fallen along the hydrodynamic branch, rises for good. This adds what the
table needs at that stress, interpolated in log-log between the curve's two
flowing points around it: the inertial number I_c and the viscous number
J = eta_f gamma_dot / P (linearly in log stress: frac_bl), and the prefactor
C = gamma_dot_c s_c / I_c^2 (which is s_c / J in these units).

A pair after --rerun is a rerun: its curves replace those with the same
sample label in the pairs before it (other pairs' curves are other curves,
whatever their label). Rows are sorted by (mu0, seed). Rates are in
eta_f/(rho_p R^2), stresses in eta_f^2/(rho_p R^2) (the sweep's units).
"""
import csv
import math
import os
import sys

HEADER = ("mu0,phi_bulk,s_c,onset_rate,onset_stress,inertial_number,viscous_number,prefactor,"
          "frac_bl_min,frac_bl_onset,seed,model,source")


def at_stress(points, stress, column, log_value=True):
    """column of the flowing points (dicts, sorted by shear_stress) at
    `stress`, interpolated in log stress between the two points around it."""
    for a, b in zip(points, points[1:]):
        low, high = float(a["shear_stress"]), float(b["shear_stress"])
        if low <= stress <= high:
            t = math.log(stress / low) / math.log(high / low)
            y0, y1 = float(a[column]), float(b[column])
            if log_value:
                return math.exp((1 - t) * math.log(y0) + t * math.log(y1))
            return (1 - t) * y0 + t * y1
    raise ValueError(f"stress {stress} outside the curve's flowing points")


def read_pairs(pairs):
    """[(curve row of curves.csv, its flowing points, source)] of the pairs in
    order; a pair given as ("--rerun", flow, curves) drops the earlier curves
    with its labels."""
    onsets = []
    for pair in pairs:
        rerun = pair[0] == "--rerun"
        flow_file, curves_file = pair[-2:]
        rows = [r for r in csv.DictReader(open(flow_file)) if r["status"] == "done"
                and r["jammed"] == "false" and r["gamma_dot"] and float(r["gamma_dot"]) > 0]
        versions = sorted({r["version"] for r in rows if r.get("version")})
        source = f"{os.path.dirname(flow_file)} (binary {', '.join(versions) or 'unknown'})"
        curves = list(csv.DictReader(open(curves_file)))
        if rerun:
            labels = {c["sample"] for c in curves}
            onsets = [o for o in onsets if o[0]["sample"] not in labels]
        for c in curves:
            points = sorted((r for r in rows if r["sample"] == c["sample"]
                             and float(r["phi"]) == float(c["phi"])),
                            key=lambda r: float(r["shear_stress"]))
            onsets.append((c, points, source))
    return onsets


def main(argv):
    args = [a for a in argv[1:] if a != "--header"]
    if len(args) < 3:
        sys.exit(__doc__)
    model, pairs, rest = args[0], [], args[1:]
    while rest:
        rerun = rest[0] == "--rerun"
        pair = rest[1:3] if rerun else rest[:2]
        if len(pair) != 2:
            sys.exit(__doc__)
        pairs.append(("--rerun", *pair) if rerun else tuple(pair))
        rest = rest[3:] if rerun else rest[2:]
    if "--header" in argv:
        print(HEADER)
    table = []
    for curve, points, source in read_pairs(pairs):
        if not curve["contact_onset_stress"]:
            continue  # frac_bl never rose for good: no onset on this curve
        stress, rate = float(curve["contact_onset_stress"]), float(curve["contact_onset_rate"])
        inertial = at_stress(points, stress, "inertial_number")
        viscous = at_stress(points, stress, "viscous_number")
        frac_bl = at_stress(points, stress, "frac_bl", log_value=False)
        s_c = float(points[0]["s_c"])
        phi_bulk = sum(float(r["phi_bulk"]) for r in points) / len(points)
        seed = points[0].get("cell.seed", "")
        table.append(((float(points[0]["mu0"]), seed),
                      f"{points[0]['mu0']},{phi_bulk:.4f},{points[0]['s_c']},{rate:.4g},"
                      f"{stress:.4g},{inertial:.4g},{viscous:.4g},{rate * s_c / inertial ** 2:.3g},"
                      f"{float(curve['frac_bl_min']):.3f},{frac_bl:.3f},{seed},{model},{source}"))
    for _, line in sorted(table, key=lambda row: row[0]):
        print(line)


if __name__ == "__main__":
    main(sys.argv)
