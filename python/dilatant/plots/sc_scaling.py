"""The onset's s_c scaling figure of docs/paper-reproduction.md (issue 15,
item 3): the literal model at nominal phi 0.62 (phi_bulk 0.607-0.615), mu0
0.4, stress ramps for s_c = 5e-6 and 5e-5 (and the s_c 5e-4 jam).

  PYTHONPATH=python python3 -m dilatant.plots.sc_scaling DOCS
    reads  DOCS/sc-scaling/flowcurves.csv            the ramps to lambda 100
                                                     (examples/paper/sc-scaling.toml)
           DOCS/sc-scaling/cold-starts/*.json        the jams' cold starts
           DOCS/sc-scaling-5e-6/summary-lambda-*.json the s_c 5e-6 ramp carried on
                                                     (scripts/ramp_from_state.sh)
           DOCS/sc-scaling-ramp/summary.json         s_c 5e-4 from the s_c 5e-5 state
    writes DOCS/sc-scaling/sc_scaling.png/.svg

Left: viscosity against shear rate; a ramp's jam is drawn at the rate of its
last flowing point (a cross), a jam's cold start that flowed as an open marker.
Right: the share of boundary-lubricated contacts against the viscous number
divided by s_c. Without fluid forces every force scales with the stress, so a
contact's Sommerfeld number s = eta_f v / N scales with J = eta_f gamma_dot / P
and contacts turn BL where J falls below J_c = s_c / c (the text's derivation):
if the frictional rise is set by the Sommerfeld number, P_BL against J / s_c
falls on one curve for every s_c there, while the viscous plateau (J fixed by
phi) need not.
"""
import glob
import json
import sys
from pathlib import Path

from .common import RATE, VISCOSITY, plt, read_rows, save

COLOURS = {"5e-06": "tab:blue", "5e-05": "tab:red", "0.0005": "tab:green"}


def number(row, key):
    value = row.get(key, "")
    return float(value) if value not in ("", None) else float("nan")


def summary_row(path):
    """A summary.json as a flowcurves.csv row (strings; s_c as the sweep spells it)."""
    with open(path) as f:
        s = json.load(f)
    row = {k: (json.dumps(v) if isinstance(v, bool) else str(v)) for k, v in s.items()}
    row["s_c"] = {5e-6: "5e-06", 5e-5: "5e-05", 5e-4: "0.0005"}.get(s["s_c"], str(s["s_c"]))
    return row


def ramps(docs):
    """{s_c label: [row, ...]} in lambda order; rows are flowcurves.csv rows or
    summaries, with `jammed` and `start` as strings."""
    out = {}
    for r in read_rows(docs / "sc-scaling" / "flowcurves.csv"):
        if r.get("status") != "done":
            continue
        out.setdefault(r["friction.s_c"], []).append(r)
    for path in sorted(glob.glob(str(docs / "sc-scaling" / "cold-starts" / "*.json"))):
        row = summary_row(path)
        row["start"] = "jam cold start"
        out.setdefault(row["s_c"], []).append(row)
    more = sorted(glob.glob(str(docs / "sc-scaling-5e-6" / "summary-lambda-*.json")),
                  key=lambda p: float(Path(p).stem.split("-")[-1]))
    for path in more:
        row = summary_row(path)
        row["start"] = "continued"
        out.setdefault("5e-06", []).append(row)
    for label in out:
        out[label].sort(key=lambda r: (number(r, "lambda"), r.get("start") == "jam cold start"))
    return out


def main():
    docs = Path(sys.argv[1])
    data = ramps(docs)
    fig, (left, right) = plt.subplots(1, 2, figsize=(10, 4.2))
    for label, rows in sorted(data.items(), key=lambda kv: float(kv[0])):
        colour = COLOURS.get(label, "k")
        again = [r.get("start") == "jam cold start" for r in rows]
        flowing = [r for r, a in zip(rows, again) if r.get("jammed") != "true" and not a]
        cold = [r for r, a in zip(rows, again) if r.get("jammed") != "true" and a]
        jams = [r for r in rows if r.get("jammed") == "true"]
        if flowing:
            left.errorbar([number(r, "gamma_dot") for r in flowing],
                          [number(r, "eta") for r in flowing],
                          yerr=[number(r, "eta_err") for r in flowing], marker="o",
                          color=colour, capsize=2, label=f"s_c {float(label):g}")
        if cold:
            left.errorbar([number(r, "gamma_dot") for r in cold], [number(r, "eta") for r in cold],
                          yerr=[number(r, "eta_err") for r in cold], marker="o", mfc="white",
                          ls="none", color=colour, capsize=2,
                          label=f"s_c {float(label):g}: the jam's cold start flows")
        for jam in jams:
            below = [r for r in flowing if number(r, "lambda") < number(jam, "lambda")]
            if below:
                left.plot([number(below[-1], "gamma_dot")], [number(below[-1], "eta")],
                          marker="x", ms=12, color=colour, ls="none")
            elif not flowing:
                left.annotate(f"s_c {float(label):g}: jams at lambda {number(jam, 'lambda'):g}",
                              xy=(0.97, 0.04), xycoords="axes fraction", color=colour,
                              fontsize=8, ha="right")
        if flowing:
            right.plot([number(r, "viscous_number") / float(label) for r in flowing],
                       [number(r, "frac_bl") for r in flowing], marker="o", color=colour,
                       label=f"s_c {float(label):g}")
        if cold:
            right.plot([number(r, "viscous_number") / float(label) for r in cold],
                       [number(r, "frac_bl") for r in cold], marker="o", mfc="white",
                       ls="none", color=colour)
    left.set_xscale("log")
    left.set_yscale("log")
    left.set_xlabel(RATE)
    left.set_ylabel(VISCOSITY)
    left.set_title("x: the ramp jams at the next lambda", fontsize=9)
    left.legend(fontsize=7)
    right.set_xscale("log")
    right.set_xlabel(r"viscous number / $s_c$, $J/s_c = \eta_f\dot\gamma/(P s_c)$")
    right.set_ylabel(r"share of BL contacts $P_{BL}$")
    right.set_title("the frictional rise against J / s_c", fontsize=9)
    right.legend(fontsize=7)
    version = sorted({r.get("version", "") for rows in data.values() for r in rows} - {""})
    fig.suptitle("literal model, nominal phi 0.62 (phi_bulk 0.607-0.615), mu0 0.4, 15 x 10 x 18 R"
                 f" (dilatant {', '.join(version)})", fontsize=9)
    fig.tight_layout()
    save(fig, docs / "sc-scaling", "sc_scaling")


if __name__ == "__main__":
    main()
