#!/usr/bin/env python3
"""Would a shorter run have given the same flow curve? (issue 34's study size)

For every finished point of a sweep folder, the wall speed (gamma_dot L_z, in the timeseries' units) averaged over the
window the point used (its summary.json: strain past transient_strain) against
the average over a shorter window (--transient, --strain: by default strain 1-3
instead of 2-6), each with the engine's block error, and the engine's
steadiness test on the shorter window. The averages and the test are those of
src/measure/flow_series_impl.hpp (steady_average: duration-weighted, 10 block
means) and src/measure/steadiness.cpp (second half against first half, steady
when the change is within max(3 sigma, 5%)); the script checks itself by
reproducing each summary's wall speed from its own window (to 1e-6).

    python3 bench/window_check.py out/paper/decisive-le-mu0.4 --out FILE.csv

A point whose short window is steady would stop there under
`run.strain = 3, run.transient_strain = 1, sweep.extend_unsteady_to`; one that
is not runs on (docs/sweeps.md "Points that are not steady"), so the question
is only whether the steady short windows agree with the long ones.
"""
import argparse
import csv
import json
import math
import os
import sys
import tomllib

BLOCKS = 10


def rows_of(path):
    with open(path, newline="") as f:
        out, t_prev = [], 0.0
        for r in csv.DictReader(f):
            t, strain = float(r["t"]), float(r["strain"])
            # a row's duration is the time since the previous row (the first
            # row of a continued point is in its transient, never averaged)
            out.append((strain, t - t_prev, float(r["wall_velocity"]), float(r["gamma_dot"])))
            t_prev = t
        return out


def average(rows, start, end, field):
    """steady_average over start < strain <= end: (mean, error, samples)."""
    sel = [r for r in rows if start < r[0] - 1e-12 <= end and r[1] > 0]
    total = sum(r[1] for r in sel)
    if not sel:
        return math.nan, 0.0, 0
    mean = sum(r[field] * r[1] for r in sel) / total
    if len(sel) < 2 * BLOCKS:
        return mean, 0.0, len(sel)
    bsum, btime, elapsed = [0.0] * BLOCKS, [0.0] * BLOCKS, 0.0
    for r in sel:
        b = min(BLOCKS - 1, int(elapsed / total * BLOCKS))
        bsum[b] += r[field] * r[1]
        btime[b] += r[1]
        elapsed += r[1]
    v = [s / t for s, t in zip(bsum, btime)]
    m = sum(v) / BLOCKS
    var = max(0.0, sum(x * x for x in v) / BLOCKS - m * m) * BLOCKS / (BLOCKS - 1)
    return mean, math.sqrt(var / BLOCKS), len(sel)


def drift(rows, start, end):
    """The steadiness test of the wall speed (field 2): (known, steady, change)."""
    last = max(r[0] for r in rows if r[0] - 1e-12 <= end)
    mid = 0.5 * (start + last)
    a = average(rows, start, mid, 2)
    b = average(rows, mid, end, 2)
    whole = average(rows, start, end, 2)
    if a[2] < 2 * BLOCKS or b[2] < 2 * BLOCKS or whole[0] == 0.0:
        return False, False, math.nan
    change = (b[0] - a[0]) / abs(whole[0])
    err = math.hypot(a[1], b[1]) / abs(whole[0])
    return True, abs(change) <= max(3.0 * err, 0.05), change


def transient_of(config):
    with open(config, "rb") as f:
        return tomllib.load(f)["run"]["transient_strain"]


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("sweep", help="a sweep folder (its points/ subfolders)")
    ap.add_argument("--transient", type=float, default=1.0, help="the short window's start")
    ap.add_argument("--strain", type=float, default=3.0, help="the short window's end")
    ap.add_argument("--out", help="CSV to write (else stdout)")
    args = ap.parse_args()
    points = os.path.join(args.sweep, "points")
    table = []
    for name in sorted(os.listdir(points)):
        folder = os.path.join(points, name)
        try:
            with open(os.path.join(folder, "summary.json")) as f:
                s = json.load(f)
        except (OSError, ValueError):
            continue  # not finished
        if s.get("jammed") or s.get("gamma_dot") is None:
            continue
        rows = rows_of(os.path.join(folder, "timeseries.csv"))
        # summary.json names its window since 0.13.0; before, the point's config.toml
        transient = s.get("transient_strain", transient_of(os.path.join(folder, "config.toml")))
        long_mean, long_err, _ = average(rows, transient, math.inf, 2)
        if abs(long_mean - s["wall_velocity"]) > 1e-6 * abs(s["wall_velocity"]):
            sys.exit(f"window_check: {folder}: wall speed {long_mean} does not reproduce "
                     f"summary.json's {s['wall_velocity']}; the averaging here is not the engine's")
        # the run to strain S stops at the first step past S: its last row may
        # sit a little above S (rows are written each 0.05 strain)
        end = args.strain + 0.01
        short_mean, short_err, n = average(rows, args.transient, end, 2)
        # the rest of the run, a window that shares no row with the short one
        rest_mean, rest_err, _ = average(rows, end, math.inf, 2)
        known, steady, change = drift(rows, args.transient, end)
        z = (short_mean - rest_mean) / math.hypot(short_err, rest_err)
        table.append({
            "point": name, "shear_stress": s["shear_stress"],
            "long_window": f"{transient:g}-{s['strain']:.3g}",
            "gamma_dot": f"{s['gamma_dot']:.6g}",
            "wall_speed_long": f"{long_mean:.6g}", "wall_speed_long_err": f"{long_err:.3g}",
            "wall_speed_short": f"{short_mean:.6g}", "wall_speed_short_err": f"{short_err:.3g}",
            "short_rows": n, "ratio": f"{short_mean / long_mean:.4f}",
            "wall_speed_rest": f"{rest_mean:.6g}", "wall_speed_rest_err": f"{rest_err:.3g}",
            "z_short_rest": f"{z:.2f}",
            "short_steady": "" if not known else str(steady).lower(),
            "short_drift": "" if not known else f"{change:+.3f}",
            "long_steady": str(s.get("steady")).lower(),
        })
    steady = [r for r in table if r["short_steady"] == "true"]
    zs = [float(r["z_short_rest"]) for r in steady]
    print(f"window_check: {len(steady)} of {len(table)} short windows steady; over them "
          f"short/rest z: mean {sum(zs) / len(zs):+.2f} +- {1 / math.sqrt(len(zs)):.2f}, "
          f"chi2 {sum(z * z for z in zs):.2f} over {len(zs)}", file=sys.stderr)
    out = open(args.out, "w", newline="") if args.out else sys.stdout
    w = csv.DictWriter(out, fieldnames=list(table[0]), lineterminator="\n")
    w.writeheader()
    w.writerows(table)


if __name__ == "__main__":
    main()
