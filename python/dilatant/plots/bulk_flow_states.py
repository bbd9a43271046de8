"""The flow states measured in the Lees–Edwards box, as the table `dilatant
predict` compiles in before the sediment's (data/jamming/bulk_flow_states.csv,
data/jamming/README.md, docs/jamming.md "The predictor's sources"):

    PYTHONPATH=python python3 -m dilatant.plots.bulk_flow_states DIR... > bulk_flow_states.csv

Every flowcurves.csv under the DIRs is read with the sweep.toml beside it. A
curve counts when its points ran in the Lees–Edwards box (`cell.boundary`),
under stress control (a ramp in lambda), with the literal model (Stribeck law,
no lubrication films, no drag), the model of the sediment table; any other
curve is named on stderr and left out. A curve is a sweep's `sample` (with
its nominal phi and seed); its points are those with status `done`, in lambda.
A curve with a point still `pending` or `failed` is a ramp not yet run to its
end (a sweep in progress, or one whose chain broke): it is named on stderr and
left out, since its last point says nothing of the stresses above it; unless
the analysis beside it calls it `dst` by a fall it places at one of its done
points (below): the fall is measured whatever the stresses above it do, so the
ramp counts, up to its last done point, and stderr names it with the points
still to run. A
refinement (`sweep.refines`: extra stresses of another sweep's ramps, each
started from that ramp's state) is left out as a whole: the refined ramp's own
table decides its row.

* no point jammed: `cst`, up to its largest lambda (`max_lambda`);
* its first (lowest-stress) point jammed: `jammed` (no flow at all);
* it flowed, then jammed at `jam_lambda`, and the sweep's cold start at that
  stress jammed too (`jam_cold_start`): `dst`. A jam without a confirming cold
  start is named on stderr and left out: it may be the ramp's history.

* it never jammed, but the flow-curve analysis in the `curves.csv` beside the
  table calls it `dst` (its rate fell as the stress rose, `rate_falls`: a step
  across an S-shaped curve's turning point; or `rate_not_increasing`,
  `n_above_cap`): `dst` with the analysis's `dst_evidence`, and `fall_lambda`,
  the lambda of the point at the analysis's `fall_stress` (the first on the
  lower branch) where the rate fell. A `rate_falls` ramp whose analysis is
  older than that column is named on stderr and left out (run `dilatant
  analyze` again), never counted `cst`.

`dst_evidence` is the analysis's word on a `dst` row (`jammed` for a
confirmed jam), empty otherwise.

phi_bulk is the curve's mean (in the Lees–Edwards box it is the box's
fraction). `max_valid_lambda` is the largest flowing lambda whose point is
`valid` (at most 5% of contacts beyond s_lim), `max_frac_unconverged` the
largest share of solver steps that hit max_iterations over the curve's points.
`source` is the flowcurves.csv as given, `sample` the curve's label in it.
"""
import csv
import sys
import tomllib
from collections import defaultdict
from pathlib import Path

HEADER = ("mu0,phi_bulk,regime,max_lambda,max_valid_lambda,jam_lambda,points,cell,seed,"
          "max_frac_unconverged,version,source,sample,dst_evidence,fall_lambda")


def setting(row, sweep, section, key):
    """A swept key is a column of the row; else the sweep's value."""
    return row.get(f"{section}.{key}") or str(sweep.get(section, {}).get(key, ""))


def why_not_bulk(row, sweep):
    """None when the point is a stress-controlled literal-model point in the
    Lees–Edwards box, else what it is instead."""
    checks = [("cell", "boundary", "lees-edwards"), ("cell", "control", "stress"),
              ("friction", "law", "stribeck"), ("fluid", "lubrication", "none"),
              ("fluid", "drag", "none")]
    # A sweep older than a key has none: it ran with the key's first value.
    default_of = {"boundary": "walls (unset: older than the key)",
                  "control": "stress (unset)"}
    for section, key, wanted in checks:
        value = setting(row, sweep, section, key).strip("'\"")
        if value == "" and key == "control":
            value = "stress"
        if value != wanted:
            return f"{section}.{key} = {value or default_of.get(key, '(unset)')}"
    return None


def cell_name(row, sweep):
    size = row.get("cell.size") or str(sweep["cell"]["size"])
    return "x".join(f"{float(v):g}" for v in size.strip("[] ").split(","))


def fmt(x):
    return "" if x is None else f"{x:g}"


def fall_lambda_of(points, fall_stress):
    """The lambda of the point at the analysis's fall_stress (written with
    fewer digits than the flow table's shear_stress: matched within 1e-6)."""
    for r in points:
        if abs(float(r["shear_stress"]) - fall_stress) <= 1e-6 * fall_stress:
            return float(r["lambda"])
    return None


def curve_row(source, sample, points, sweep, analysed=None):
    """One table row, or None and why not. analysed: the analysis's
    (dst_evidence, fall_stress or None) when it calls the curve dst without a
    jam."""
    points.sort(key=lambda r: float(r["lambda"]))
    jammed = [r for r in points if r["jammed"] == "true"]
    first_jam = float(jammed[0]["lambda"]) if jammed else None
    flowing = [r for r in points if r["jammed"] != "true"
               and (first_jam is None or float(r["lambda"]) < first_jam)]
    evidence, fall_lambda = "", None
    if not jammed and analysed is not None:
        regime, (evidence, fall_stress) = "dst", analysed
        fall_lambda = None if fall_stress is None else fall_lambda_of(points, fall_stress)
        if fall_stress is not None and fall_lambda is None:
            return None, (f"{source} {sample}: no point at the analysis's fall_stress "
                          f"{fall_stress:g} (curves.csv and the table disagree)")
    elif not jammed:
        regime = "cst"
    elif not flowing:
        regime = "jammed"
    elif jammed[0].get("jam_cold_start") == "jammed":
        regime, evidence = "dst", "jammed"
    else:
        return None, (f"{source} {sample}: jammed at lambda {first_jam:g} without a cold start "
                      "that confirms it")
    valid = [float(r["lambda"]) for r in flowing if r["valid"] == "true"]
    phi_bulk = sum(float(r["phi_bulk"]) for r in points) / len(points)
    unconverged = max(float(r["frac_steps_unconverged"] or 0) for r in points)
    versions = "+".join(sorted({r["version"] for r in points}))
    row = [fmt(float(points[0]["mu0"])), f"{phi_bulk:.4f}", regime,
           fmt(float(flowing[-1]["lambda"]) if flowing else None), fmt(max(valid, default=None)),
           fmt(first_jam), str(len(points)), cell_name(points[0], sweep),
           points[0].get("cell.seed") or str(sweep["cell"].get("seed", 1)), f"{unconverged:.2g}",
           versions, source, sample, evidence, fmt(fall_lambda)]
    if any("," in field for field in row):
        return None, f"{source} {sample}: a field holds a comma: {row}"
    return ",".join(row), None


ORDER = {"cst": 0, "dst": 1, "jammed": 2}


def contradictions(rows):
    """Pairs of rows of one mu0 where the weaker state (cst < dst < jammed) is
    at or above the stronger one in phi: the order predict's rule assumes."""
    fields = [row.split(",") for row in rows]
    out = []
    for lo in fields:
        for hi in fields:
            if (float(lo[0]) == float(hi[0]) and ORDER[lo[2]] < ORDER[hi[2]]
                    and float(lo[1]) >= float(hi[1])):
                out.append(f"{lo[2]} at {lo[1]} ({lo[11]} {lo[12]}) against {hi[2]} at {hi[1]} "
                           f"({hi[11]} {hi[12]})")
    return out


def analysed_dst(curves_file):
    """The samples the flow-curve analysis beside the table calls DST by a rule
    other than a jam, each with (dst_evidence, fall_stress or None: no fall, or
    an analysis older than the column); none when there is no analysis."""
    if not curves_file.exists():
        return {}
    return {r["sample"]: (r["dst_evidence"],
                          float(r["fall_stress"]) if r.get("fall_stress") else None)
            for r in csv.DictReader(open(curves_file))
            if r["regime"] == "dst" and r.get("dst_evidence") not in ("", "jammed", None)}


def rows_of(flow_file):
    with open(flow_file.parent / "sweep.toml", "rb") as f:
        sweep = tomllib.load(f)
    refines = sweep.get("sweep", {}).get("refines")
    if refines:
        return [], [f"{flow_file}: a refinement of the ramps in {refines}, whose table decides"], []
    # skipped: curves left out, and why; notes: curves counted, with a caveat
    curves, skipped, notes = defaultdict(list), [], []
    unfinished = defaultdict(int)
    for r in csv.DictReader(open(flow_file)):
        key = (r["sample"], r["phi"], r.get("cell.seed", ""))
        if r["status"] in ("pending", "failed"):
            unfinished[key] += 1
        if r["status"] != "done":
            continue
        why = why_not_bulk(r, sweep)
        if why:
            skipped.append(f"{flow_file} {r['sample']}: {why}")
            continue
        curves[key].append(r)
    dst_without_jam = analysed_dst(flow_file.parent / "curves.csv")
    out = []
    for key, points in curves.items():
        sample = key[0]
        analysed = dst_without_jam.get(sample)
        if unfinished[key]:
            fall = None if analysed is None or analysed[1] is None else fall_lambda_of(
                points, analysed[1])
            if fall is None:
                skipped.append(f"{flow_file} {sample}: the ramp is not finished "
                               f"({unfinished[key]} points pending or failed)")
                continue
            notes.append(f"{flow_file} {sample}: counted though not finished: dst by "
                           f"{analysed[0]}, its rate fell at lambda {fall:g}; "
                           f"{unfinished[key]} points above still pending or failed")
        if analysed == ("rate_falls", None):
            skipped.append(f"{flow_file} {sample}: dst by rate_falls in an analysis without "
                           "fall_stress (older than 0.12.0): run `dilatant analyze` again")
            continue
        row, why = curve_row(flow_file.as_posix(), sample, points, sweep, analysed)
        if row:
            out.append((float(points[0]["mu0"]), row))
        else:
            skipped.append(why)
    return out, sorted(set(skipped)), notes


def main(argv):
    if len(argv) < 2:
        sys.exit(__doc__)
    rows, skipped, notes = [], [], []
    for d in argv[1:]:
        for flow in sorted(Path(d).rglob("flowcurves.csv")):
            if not (flow.parent / "sweep.toml").exists():
                skipped.append(f"{flow}: no sweep.toml beside it")
                continue
            r, s, n = rows_of(flow)
            rows += r
            skipped += s
            notes += n
    for s in skipped:
        print(f"left out: {s}", file=sys.stderr)
    for n in notes:
        print(n, file=sys.stderr)
    clashes = contradictions([row for _, row in rows])
    if clashes:
        # `dilatant predict` refuses such a table (and would then refuse every
        # query): the measured curves disagree, and a person must decide why.
        sys.exit("bulk_flow_states: curves contradict each other (a ramp flows at or above a "
                 "fraction where another of its mu0 jams):\n  " + "\n  ".join(clashes))
    print(HEADER)
    for _, row in sorted(rows, key=lambda item: item[0]):
        print(row)


if __name__ == "__main__":
    main(sys.argv)
