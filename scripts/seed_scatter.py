#!/usr/bin/env python3
"""Seed-to-seed scatter of a shear-cell quantity, and the size a seed-averaged
test needs to catch a given bias (docs/testing.md "Sizing the seed-averaged
suites").

    seed_scatter.py --out DIR [--binary build/dilatant] [--seeds 12] [--jobs 2]
                    [--strain 10] [--transient 2] [--windows 1 2 4 8]
                    [--quantity gamma_dot ...] [--bias 0.05 ...] -- --set KEY=VALUE ...

Runs the cell given by the --set overrides once per seed (cell.seed = 1..N,
resumed from DIR if already there), and for each steady window of T strain
after the transient prints the seed mean of the quantity's time average and
the relative standard deviation s(T) between seeds. If the seeds' averages
decorrelate within the window, s(T)^2 T is a constant v, the relative variance
per unit strain; the scatter of a seed mean of n runs of T strain is then
sqrt(v / (n T)).

A test comparing two settings' seed means fails when they differ by more than
3 combined standard errors, sqrt(2 v / (n T)) with equal sizes. It catches a
relative bias delta at three combined standard errors when
    3 sqrt(2 v / (n T)) <= delta,   i.e.   n T >= 18 v / delta^2
(a shift of exactly delta then fails the test half the time, 4/3 delta 84%,
5/3 delta 98%). The table gives n T for each --bias.
"""
import argparse
import concurrent.futures
import csv
import json
import math
import os
import pathlib
import statistics
import subprocess
import sys


def run_seed(binary, out, seed, strain, transient, overrides):
    folder = out / f"s{seed}"
    if (folder / "summary.json").exists():
        return folder
    command = [binary, "run", "--quiet", "--out", str(folder), "--set", f"cell.seed={seed}",
               "--set", f"run.strain={strain}", "--set", f"run.transient_strain={transient}",
               "--set", "solver.threads=1", *overrides]
    subprocess.run(command, check=True, stdout=subprocess.DEVNULL)
    return folder


def window_average(folder, quantity, start, end):
    """Time average of the time series' column over strain (start, end]."""
    total = weighted = 0.0
    previous_t = None
    with open(folder / "timeseries.csv", encoding="utf-8") as f:
        for row in csv.DictReader(f):
            t, strain = float(row["t"]), float(row["strain"])
            if previous_t is not None and start < strain <= end + 1e-9:
                dt = t - previous_t
                total += dt
                weighted += dt * float(row[quantity])
            previous_t = t
    return weighted / total if total > 0 else math.nan


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--out", required=True, type=pathlib.Path)
    parser.add_argument("--binary", default="build/dilatant")
    parser.add_argument("--seeds", type=int, default=12)
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--strain", type=float, default=10.0)
    parser.add_argument("--transient", type=float, default=2.0)
    parser.add_argument("--windows", type=float, nargs="+", default=[1, 2, 4, 8])
    parser.add_argument("--quantity", nargs="+", default=["gamma_dot"])
    parser.add_argument("--bias", type=float, nargs="+", default=[0.05])
    parser.add_argument("overrides", nargs=argparse.REMAINDER)
    args = parser.parse_args()
    overrides = [o for o in args.overrides if o != "--"]
    args.out.mkdir(parents=True, exist_ok=True)

    with concurrent.futures.ThreadPoolExecutor(args.jobs) as pool:
        folders = list(pool.map(
            lambda s: run_seed(args.binary, args.out, s, args.strain, args.transient, overrides),
            range(1, args.seeds + 1)))

    rows = []
    print(f"{args.seeds} seeds of {args.strain} strain, steady from {args.transient}; "
          f"n T needed per bias at 3 combined standard errors (two settings)")
    print("quantity\tT\tmean\ts(T)\tv=s^2 T\t" + "\t".join(f"nT@{b:g}" for b in args.bias))
    for quantity in args.quantity:
        for window in args.windows:
            end = args.transient + window
            if end > args.strain + 1e-9:
                continue
            values = [window_average(f, quantity, args.transient, end) for f in folders]
            mean = statistics.fmean(values)
            s = statistics.stdev(values) / abs(mean)
            v = s * s * window
            need = [18.0 * v / (b * b) for b in args.bias]
            rows.append({"quantity": quantity, "window": window, "mean": mean, "s": s, "v": v,
                         "values": values, "nT": dict(zip(map(str, args.bias), need))})
            print(f"{quantity}\t{window:g}\t{mean:.4g}\t{s:.3f}\t{v:.4f}\t" +
                  "\t".join(f"{n:.0f}" for n in need))
    (args.out / "scatter.json").write_text(json.dumps(
        {"overrides": overrides, "seeds": args.seeds, "strain": args.strain,
         "transient": args.transient, "rows": rows}, indent=1))
    return 0


if __name__ == "__main__":
    sys.exit(main())
