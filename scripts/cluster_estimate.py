#!/usr/bin/env python3
"""Expected wall time of committed sweeps on K MPI ranks (docs/cluster.md).

Reads the per-point wall times (column wall_time_s) of the committed sweeps,
docs/paper-reproduction/<sweep>/flowcurves.csv, rebuilds their units of work
as `dilatant sweep` forms them (one point, or with continuation one chain: the
points of a flow curve, equal in every swept key but fluid.lambda) and replays
the MPI scheduler: units in the order of the sweep, each to the first rank
that is free (sweep/mpi_scheduler.hpp). Per unit and per sweep it needs:

  * done points: their own wall_time_s;
  * skipped points (above a jam): nothing;
  * pending points (not run in the committed table): the median wall time of
    the sweep's done points that started the same way (cold or continued);
  * jam confirmations (jam_cold_start not empty): one cold start, costed as
    the chain's first point (a cold start, packing included) -- their own wall
    time is in the point's cold-start/summary.json, which is not committed.

The wall times were measured on the 2-core development machine with two
points side by side, so one point had one core: the estimate assumes a
cluster core as fast as one of those.

    python3 scripts/cluster_estimate.py [--ranks 1 2 64] [SWEEP ...]
"""
import argparse
import csv
import heapq
import pathlib
import statistics

DOCS = pathlib.Path(__file__).resolve().parent.parent / "docs" / "paper-reproduction"
PAPER_STUDY = ("fig2 coulomb boundary dst-checks dense-window newtonian-fluid newtonian-phi "
               "dense-window-phi dst-map dst-map-mu0 dst-map-phi sc-scaling").split()
DST_MAP = ["dst-map", "dst-map-mu0", "dst-map-phi"]


def units_of(sweep):
    """The units of work of a sweep, in the order the scheduler hands them out,
    each as its cost in seconds."""
    rows = list(csv.DictReader(open(DOCS / sweep / "flowcurves.csv")))
    done = [r for r in rows if r["status"] == "done" and r["wall_time_s"]]
    median = {
        kind: statistics.median([float(r["wall_time_s"]) for r in done
                                 if (r["start"] == "cold") == (kind == "cold")] or [0.0])
        for kind in ("cold", "continued")
    }

    def cost(r):
        if r["status"] == "skipped":
            return 0.0
        if r["status"] == "done" and r["wall_time_s"]:
            return float(r["wall_time_s"])
        return median["cold" if r["start"] == "cold" else "continued"]

    by_dir = {r["dir"]: r for r in rows}
    chains = {}  # first point's dir -> [rows], following the start column
    order = []
    for r in rows:
        head = r
        while head["start"] != "cold" and head["start"] in by_dir:
            head = by_dir[head["start"]]
        if head["dir"] not in chains:
            chains[head["dir"]] = []
            order.append(head["dir"])
        chains[head["dir"]].append(r)
    units = []
    for d in order:
        chain = chains[d]
        total = sum(cost(r) for r in chain)
        total += sum(cost(chain[0]) for r in chain if r.get("jam_cold_start"))
        units.append(total)
    return units


def makespan(units, ranks):
    """The scheduler's replay: each unit, in order, to the first free rank."""
    free = [0.0] * ranks
    heapq.heapify(free)
    end = 0.0
    for u in units:
        start = heapq.heappop(free)
        heapq.heappush(free, start + u)
        end = max(end, start + u)
    return end


def hours(seconds):
    return f"{seconds / 3600:.2f} h" if seconds >= 3600 else f"{seconds / 60:.0f} min"


def report(name, sweeps, ranks):
    print(f"{name}:")
    total = {k: 0.0 for k in ranks}
    work = 0.0
    pooled = []
    for s in sweeps:
        units = units_of(s)
        work += sum(units)
        pooled += units
        spans = [makespan(units, k) for k in ranks]
        for k, t in zip(ranks, spans):
            total[k] += t
        print(f"  {s:18s} {len(units):3d} units, {hours(sum(units)):>9s} of work, longest unit "
              f"{hours(max(units)):>8s}; " +
              ", ".join(f"{k} ranks {hours(t)}" for k, t in zip(ranks, spans)))
    print(f"  all, one sweep after the other: {hours(work)} of work; " +
          ", ".join(f"{k} ranks {hours(total[k])}" for k in ranks))
    # Run side by side in one allocation, no schedule beats the longest unit
    # or the work shared evenly.
    print("  bound for all side by side, max(longest unit, work / ranks): " +
          ", ".join(f"{k} ranks {hours(max(max(pooled), work / k))}" for k in ranks))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--ranks", type=int, nargs="+", default=[1, 2, 64])
    parser.add_argument("sweeps", nargs="*")
    args = parser.parse_args()
    if args.sweeps:
        report("sweeps", args.sweeps, args.ranks)
    else:
        report("the paper study (scripts/docs-paper.sh)", PAPER_STUDY, args.ranks)
        report("the DST map", DST_MAP, args.ranks)


if __name__ == "__main__":
    main()
