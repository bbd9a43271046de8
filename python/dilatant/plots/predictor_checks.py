"""`dilatant predict` held against every flow curve in docs/paper-reproduction
(docs/jamming.md "Cross-checks"):

  PYTHONPATH=python python3 -m dilatant.plots.predictor_checks DILATANT OUT.csv DIR...

For each flowcurves.csv under the DIRs, each curve with two lambdas or more
(same friction law and fluid forces, mu0, nominal phi, seed, s_c and `sample`, the
table's curve label, which names every other swept key such as the cell's size)
gets its mean phi_bulk,
the regime `dilatant predict` gives there from the sediment table alone
(`--bulk-table none`: the bulk table is read from some of these very curves, so
it would check itself), and what the curve did: the lambda range run, whether a point
jammed (and the first lambda that did, and whether the sweep's cold start at
that stress jammed too: `jam_cold_start`), the regime the flow-curve analysis
beside the table (`curves.csv`) gives the curve (`analysis`: `dst rate_falls`,
`cst`, ...), and eta at the highest lambda over eta at the lowest (thickening
when > 1). `observed` sums it up: `jams` (a jam its cold start confirms),
`jams in the ramp only` (its cold start flows), `jams without a cold start`, `dst without
a jam` (the analysis's dst in a curve that never jammed: under imposed stress
its rate fell, or did not rise, as the stress rose) or `flows`. Written to
OUT.csv (via OUT.csv.part). A
refinement's table (sweep.refines) is left out: its curves are extra points of
another table's ramps.
"""
import csv
import json
import os
import subprocess
import sys
import tomllib
from collections import defaultdict
from pathlib import Path


def model(row, fluid):
    """'stribeck', 'stribeck+films+drag', ...: the friction law and the fluid
    forces of the row (a swept fluid key is a column, else the sweep's)."""
    name = row["friction_law"]
    if (row.get("fluid.lubrication") or fluid.get("lubrication", "none")) != "none":
        name += "+films"
    if (row.get("fluid.drag") or fluid.get("drag", "none")) != "none":
        name += "+drag"
    return name


def curves(flow_file):
    with open(flow_file.parent / "sweep.toml", "rb") as f:
        sweep = tomllib.load(f)
    fluid = sweep.get("fluid", {})
    groups = defaultdict(list)
    if sweep.get("sweep", {}).get("refines"):
        return groups
    for r in csv.DictReader(open(flow_file)):
        if r["status"] != "done":
            continue
        key = (model(r, fluid), float(r["mu0"]), float(r["phi"]),
               r.get("cell.seed") or "1", r["s_c"], r["sample"])
        groups[key].append(r)
    # A flow curve has two lambdas at least; single points are not curves.
    return {k: v for k, v in groups.items() if len({r["lambda"] for r in v}) > 1}


def analysed(flow_file):
    """The analysis's regime of each curve of the table, keyed by its sample
    and nominal phi (a sample may hold several phi): `dst rate_falls`, `cst`
    ({} when the table has no curves.csv beside it)."""
    path = flow_file.parent / "curves.csv"
    if not path.is_file():
        return {}
    return {(r["sample"], float(r["phi"])):
            " ".join(w for w in (r["regime"], r.get("dst_evidence", "")) if w)
            for r in csv.DictReader(open(path))}


def observed(first_jam, cold_start, analysis):
    """What the curve did, in the words of docs/jamming.md's record."""
    if first_jam is not None:
        return {"jammed": "jams", "flowed": "jams in the ramp only"}.get(
            cold_start, "jams without a cold start")
    return "dst without a jam" if analysis.startswith("dst") else "flows"


def main(argv):
    if len(argv) < 4:
        sys.exit(__doc__)
    binary, out = argv[1], Path(argv[2])
    rows = []
    for d in argv[3:]:
        for flow in sorted(Path(d).rglob("flowcurves.csv")):
            regimes = analysed(flow)
            for (law, mu0, phi, seed, s_c, sample), points in sorted(curves(flow).items()):
                points.sort(key=lambda r: float(r["lambda"]))
                fractions = [float(r["phi_bulk"]) for r in points if r["phi_bulk"]]
                phi_bulk = sum(fractions) / len(fractions)
                jams = [r for r in points if r["jammed"] == "true"]
                first_jam = float(jams[0]["lambda"]) if jams else None
                cold_start = jams[0].get("jam_cold_start", "") if jams else ""
                flowing = [r for r in points if r["jammed"] != "true" and r["eta"]]
                ratio = (float(flowing[-1]["eta"]) / float(flowing[0]["eta"])
                         if len(flowing) > 1 else "")
                p = json.loads(subprocess.run(
                    [binary, "predict", "--mu0", str(mu0), "--phi", f"{phi_bulk:.4f}", "--json",
                     "--bulk-table", "none"],
                    check=True, capture_output=True, text=True).stdout)
                rows.append({
                    "source": str(flow.parent), "model": law, "mu0": mu0, "phi": phi,
                    "seed": seed, "s_c": s_c, "phi_bulk": f"{phi_bulk:.4f}",
                    "predicted": p["regime"] + (" (uncertain)" if p["uncertain"] else ""),
                    "phi_max_bl": p["phi_max_bl"],
                    "lambda_min": points[0]["lambda"], "lambda_max": points[-1]["lambda"],
                    "first_jam_lambda": first_jam if jams else "",
                    "eta_ratio": f"{ratio:.3g}" if ratio != "" else "",
                    "sample": sample, "jam_cold_start": cold_start,
                    "analysis": regimes.get((sample, phi), ""),
                    "observed": observed(first_jam, cold_start, regimes.get((sample, phi), "")),
                })
    part = out.with_name(out.name + ".part")
    with open(part, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        w.writeheader()
        w.writerows(rows)
    os.replace(part, out)


if __name__ == "__main__":
    main(sys.argv)
