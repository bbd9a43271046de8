"""Where contacts leave the hydrodynamic branch, measured on a sweep's flow
curves: the table `dilatant predict` compiles in (data/jamming/onsets.csv,
docs/jamming.md "The onset scale").

    PYTHONPATH=python python3 -m dilatant.plots.onset_table [--header] MODEL \\
        SWEEP/flowcurves.csv [[--rerun] SWEEP2/flowcurves.csv ...] >> onsets.csv

The paper (p. 2) puts the onset where a typical contact's Sommerfeld number
falls below s_c: on the hydrodynamic (HD) branch the fraction of boundary-
lubricated (BL) contacts falls as the stress rises, and above the onset it
rises for good. So along each curve, in order of stress, the onset is where
`frac_bl` first exceeds the curve's minimum by FRAC_BL_RISE, after that
minimum; the stress is interpolated in log between the two points around the
crossing (linearly in frac_bl), the rate, the inertial number and the
viscous number J = eta_f gamma_dot / P in log-log at that stress; the
prefactor is C = gamma_dot_c s_c / I_c^2 (which is s_c / J in these units). This is not the first rise of the viscosity (`dilatant analyze`'s
onset, 1.1 x the Newtonian plateau): at phi_bulk 0.61 that rise is inertial,
with frac_bl still falling, and does not move with s_c
(docs/paper-reproduction.md "The onset's s_c scaling").

Curves are the `sample` labels of each file (seed and mu0); a file after
--rerun is a rerun: its curves replace those with the same label in the files
before it (other files' curves are other curves, whatever their label). Only points that
finished and flow count; a curve whose frac_bl does not rise by FRAC_BL_RISE
(it jams first, or ends) has no onset and no row. Rates are in
eta_f/(rho_p R^2), stresses in eta_f^2/(rho_p R^2) (the sweep's units).
"""
import csv
import math
import os
import sys

HEADER = ("mu0,phi_bulk,s_c,onset_rate,onset_stress,inertial_number,viscous_number,prefactor,"
          "frac_bl_min,frac_bl_onset,"
          "seed,model,source")

# How far frac_bl must rise above its minimum: more than the largest
# difference between the two seeds' frac_bl at one point of the decisive
# study's ramps (0.042: mu0 0.4 at lambda 0.1, 0.221 against 0.263;
# docs/jamming.md "The onset scale"), so that seed scatter alone does not
# make an onset.
FRAC_BL_RISE = 0.05


def log_between(a, b, t):
    return math.exp((1 - t) * math.log(a) + t * math.log(b))


def frictional_onset(points, rise=FRAC_BL_RISE):
    """points: (stress, rate, frac_bl, *more) of one curve, any order, `more`
    positive (the inertial number, ...). Returns (stress, rate, more at the
    onset, frac_bl's minimum), or None when frac_bl never rises by `rise`
    after its minimum."""
    points = sorted(points)
    low = min(range(len(points)), key=lambda k: points[k][2])
    threshold = points[low][2] + rise
    for k in range(low + 1, len(points)):
        if points[k][2] > threshold:
            a, b = points[k - 1], points[k]
            t = (threshold - a[2]) / (b[2] - a[2])
            more = tuple(log_between(x, y, t) for x, y in zip(a[3:], b[3:]))
            return log_between(a[0], b[0], t), log_between(a[1], b[1], t), more, points[low][2]
    return None


def read_curves(files):
    """[(label, source, rows)] of the files in order; a file given as
    ("--rerun", path) drops the earlier curves with its labels."""
    curves = []
    for path in files:
        rerun = isinstance(path, tuple)
        path = path[1] if rerun else path
        rows = [r for r in csv.DictReader(open(path)) if r["status"] == "done"
                and r["jammed"] == "false" and r["gamma_dot"] and float(r["gamma_dot"]) > 0]
        versions = sorted({r["version"] for r in rows if r.get("version")})
        source = f"{os.path.dirname(path)} (binary {', '.join(versions) or 'unknown'})"
        labels = list(dict.fromkeys(r["sample"] for r in rows))
        if rerun:
            curves = [c for c in curves if c[0] not in labels]
        curves += [(label, source, [r for r in rows if r["sample"] == label]) for label in labels]
    return curves


def main(argv):
    args = [a for a in argv[1:] if a != "--header"]
    if len(args) < 2 or args[-1] == "--rerun":
        sys.exit(__doc__)
    model, files = args[0], []
    for k, a in enumerate(args[1:], 1):
        if a != "--rerun":
            files.append(("--rerun", a) if args[k - 1] == "--rerun" else a)
    if "--header" in argv:
        print(HEADER)
    table = []
    for label, source, rows in read_curves(files):
        points = [(float(r["shear_stress"]), float(r["gamma_dot"]), float(r["frac_bl"]),
                   float(r["inertial_number"]), float(r["viscous_number"])) for r in rows]
        onset = frictional_onset(points)
        if onset is None:
            continue
        stress, rate, (inertial, viscous), frac_bl_min = onset
        s_c = float(rows[0]["s_c"])
        phi_bulk = sum(float(r["phi_bulk"]) for r in rows) / len(rows)
        seed = rows[0].get("cell.seed", "")
        table.append(((float(rows[0]["mu0"]), seed),
                      f"{rows[0]['mu0']},{phi_bulk:.4f},{rows[0]['s_c']},{rate:.4g},{stress:.4g},"
                      f"{inertial:.4g},{viscous:.4g},{rate * s_c / inertial ** 2:.3g},{frac_bl_min:.3f},{frac_bl_min + FRAC_BL_RISE:.3f},"
                      f"{seed},{model},{source}"))
    for _, line in sorted(table, key=lambda row: row[0]):
        print(line)


if __name__ == "__main__":
    main(sys.argv)
