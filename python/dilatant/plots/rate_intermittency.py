"""Whether a stress-controlled point flows smoothly or stops and goes: the
shear rate interval by interval over the part of the run its averages use.

    PYTHONPATH=python python3 -m dilatant.plots.rate_intermittency OUT_DIR SWEEP_DIR... \\
        [--figure POINT_DIR ...]

SWEEP_DIR is a sweep's output folder (out/paper/NAME) or its archive
(runs/NAME, timeseries gzipped): every point folder under SWEEP_DIR/points/
with a summary.json is read, but a jammed one (its summary's `jammed`: the
cell stopped, there is no flow to be intermittent). Writes OUT_DIR/intermittency.csv, one row per
point, and, with --figure, OUT_DIR/rate_series.{png,svg}: the rate against
strain of the named points, beside every point's time-mean rate.

The intervals are those between consecutive rows of timeseries.csv (one row
per run.output_interval of strain) past the point's run.transient_strain
(config.toml), the window the summary averages. An interval's rate is its
strain over its time. The rows are equally spaced in strain, so the rate
over the window (strain over time, what the summary's gamma_dot measures) is
the harmonic mean of the interval rates: time_mean_over_median is about
1 - cv^2 for small fluctuations, and far below 1 when a few slow intervals
take most of the time. An interval is `slow` when its rate is below
SLOW_FRACTION of the point's median; slow_time_share is the share of the
window's time they take. Rates are relative to the median, so no unit enters
(the series are in the run's internal units, which change with lambda).
Needs Debian's python3-matplotlib and python3-numpy for the figure only.
"""
import csv
import gzip
import io
import json
import math
import statistics
import sys
import tomllib
from pathlib import Path

# A quarter of the median. On the decisive study's 60 points off the falling
# middle (2026-11-29; 40 or 80 intervals each, cv 0.07-0.48;
# docs/paper-reproduction.md "Stop and go on the falling middle") the slowest
# interval is 0.40 of its median or faster (0.50 but at one point).
SLOW_FRACTION = 0.25

HEADER = ("sweep,point,seed,mu0,lambda,shear_stress,gamma_dot,steady,valid,version,intervals,"
          "cv,min_over_median,max_over_median,time_mean_over_median,slow_intervals,slow_time_share")


def read_series(folder):
    """(time, strain) lists of a point folder's timeseries.csv or .csv.gz."""
    plain, packed = folder / "timeseries.csv", folder / "timeseries.csv.gz"
    if plain.is_file():
        text = plain.read_text()
    elif packed.is_file():
        text = gzip.decompress(packed.read_bytes()).decode()
    else:
        raise FileNotFoundError(f"{folder}: no timeseries.csv(.gz)")
    rows = list(csv.DictReader(io.StringIO(text)))
    return [float(r["t"]) for r in rows], [float(r["strain"]) for r in rows]


def interval_rates(time, strain, transient_strain):
    """[(duration, rate)] of the intervals between rows past transient_strain."""
    kept = [(t, s) for t, s in zip(time, strain) if s > transient_strain]
    out = []
    for (t0, s0), (t1, s1) in zip(kept, kept[1:]):
        if t1 <= t0:
            raise ValueError(f"time does not increase at strain {s1}")
        out.append((t1 - t0, (s1 - s0) / (t1 - t0)))
    return out


def measures(intervals):
    """The point's intermittency measures (see the module's text)."""
    if len(intervals) < 2:
        raise ValueError("fewer than two intervals past the transient")
    rates = [r for _, r in intervals]
    median = statistics.median(rates)
    mean = statistics.fmean(rates)
    total_time = sum(d for d, _ in intervals)
    time_mean = sum(d * r for d, r in intervals) / total_time
    slow = [(d, r) for d, r in intervals if r < SLOW_FRACTION * median]
    return {
        "intervals": len(intervals),
        "cv": statistics.pstdev(rates) / mean,
        "min_over_median": min(rates) / median,
        "max_over_median": max(rates) / median,
        "time_mean_over_median": time_mean / median,
        "slow_intervals": len(slow),
        "slow_time_share": sum(d for d, _ in slow) / total_time,
    }


def read_point(folder):
    """A finished point: its summary, its config's [run] and [cell], its intervals."""
    summary = json.loads((folder / "summary.json").read_text())
    config = tomllib.loads((folder / "config.toml").read_text())
    time, strain = read_series(folder)
    return summary, config, interval_rates(time, strain, config["run"]["transient_strain"])


def row(sweep, folder):
    summary, config, intervals = read_point(folder)
    m = measures(intervals)
    fields = [sweep, folder.name, config["cell"].get("seed", ""), summary["mu0"], summary["lambda"],
              summary["shear_stress"], summary["gamma_dot"], summary["steady"], summary["valid"],
              summary.get("version", "unknown"), m["intervals"]]
    fields += [m[k] for k in ("cv", "min_over_median", "max_over_median", "time_mean_over_median")]
    fields += [m["slow_intervals"], m["slow_time_share"]]
    return [f"{f:.4g}" if isinstance(f, float) else str(f).lower() if isinstance(f, bool) else str(f)
            for f in fields]


def point_folders(sweep_dir):
    """The finished points that flowed (a jammed one has no rate to measure)."""
    return sorted(p.parent for p in Path(sweep_dir).glob("points/*/summary.json")
                  if not json.loads(p.read_text()).get("jammed", False))


def draw(out, rows, figure_points):
    from .common import plt, save

    fig = plt.figure(figsize=(10, 1.2 + 1.4 * max(len(figure_points), 3)), layout="constrained")
    grid = fig.add_gridspec(len(figure_points), 2)
    means = fig.add_subplot(grid[:, 1])
    for i, folder in enumerate(figure_points):
        summary, config, intervals = read_point(folder)
        median = statistics.median(r for _, r in intervals)
        time, strain = read_series(folder)
        # The whole run, its transient too, each interval against the window's median.
        series = fig.add_subplot(grid[i, 0])
        whole = interval_rates(time, strain, -math.inf)
        series.step(strain[1:], [r / median for _, r in whole], where="pre", color="C0", lw=1)
        series.axvline(config["run"]["transient_strain"], color="grey", lw=1)
        series.axhline(SLOW_FRACTION, color="grey", ls=":", lw=1)
        series.set(yscale="log", ylim=(0.05, 3), xlim=(0, None), ylabel="rate / median")
        series.set_title(f"mu0 {summary['mu0']:g}, seed {config['cell'].get('seed', '')}, "
                         f"tau {summary['shear_stress']:.3g}: gamma_dot {summary['gamma_dot']:.3g}",
                         fontsize=8)
        if i == len(figure_points) - 1:
            series.set_xlabel("strain (averaged right of the grey line; dotted: slow)")
    rows = [dict(zip(HEADER.split(","), r)) for r in rows]
    for mu0 in sorted({float(r["mu0"]) for r in rows}):
        mine = [r for r in rows if float(r["mu0"]) == mu0]
        steady, unsteady = ([[float(r[column]) for r in mine if (r["steady"] == "true") == flag]
                             for column in ("shear_stress", "time_mean_over_median")]
                            for flag in (True, False))
        line = means.plot(*steady, "o", label=f"mu0 {mu0:g}")[0]
        if unsteady[0]:
            means.plot(*unsteady, "o", mfc="none", color=line.get_color())
    means.set(xscale="log", xlabel=r"shear stress $\tau$", ylim=(0, 1.2),
              ylabel="time-mean rate / median rate", title="every point (hollow: not steady)")
    means.legend(fontsize=7)
    versions = sorted({r["version"] for r in rows})
    sweeps = len({r["sweep"] for r in rows})
    fig.suptitle(f"Stop-and-go or smooth: {len(rows)} points of {sweeps} sweeps "
                 f"(dilatant {', '.join(versions)})", fontsize=9)
    save(fig, out, "rate_series")


def main(argv):
    args = argv[1:]
    figure_points = []
    if "--figure" in args:
        at = args.index("--figure")
        figure_points, args = [Path(p) for p in args[at + 1:]], args[:at]
    if len(args) < 2:
        sys.exit(__doc__)
    out = Path(args[0])
    for sweep in args[1:]:
        if not (Path(sweep) / "points").is_dir():
            sys.exit(f"rate_intermittency: {sweep}/points: no such folder")
    rows = [row(Path(s).name, f) for s in args[1:] for f in point_folders(s)]
    if not rows:
        sys.exit(f"rate_intermittency: no finished point under {', '.join(args[1:])}")
    out.mkdir(parents=True, exist_ok=True)
    part = out / "intermittency.csv.part"
    part.write_text("\n".join([HEADER] + [",".join(r) for r in rows]) + "\n")
    part.replace(out / "intermittency.csv")
    if figure_points:
        draw(out, rows, figure_points)


if __name__ == "__main__":
    main(sys.argv)
