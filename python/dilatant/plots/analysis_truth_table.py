"""Recovered vs true values of the analysis example, as Markdown tables.

Usage: PYTHONPATH=python python3 -m dilatant.plots.analysis_truth_table \\
           OUT_DIR TRUTH_JSON > table.md
OUT_DIR is a `dilatant analyze` output folder of examples/analysis/manifest.toml,
TRUTH_JSON the generator's examples/analysis/truth.json. Standard library only.
"""
import csv
import json
import sys
from pathlib import Path


def pm(value, err, digits=3):
    if value is None:
        return "-"
    text = f"{value:.{digits}g}"
    return text + (f" ± {err:.2g}" if err is not None else "")


def main():
    out, truth = Path(sys.argv[1]), json.loads(Path(sys.argv[2]).read_text())
    fits = json.loads((out / "fits.json").read_text())
    rows = list(csv.DictReader(open(out / "curves.csv", newline="")))
    print("| sample | phi_max true | phi_max recovered | source | A (true 0.12) | "
          "alpha (true 0.9) | chi2/dof |")
    print("|---|---|---|---|---|---|---|")
    for name, s in fits["samples"].items():
        true_pm = truth["samples"][name]["phi_max"]
        if s["phi_max_source"] == "given":
            free = s["free_fit"]
            got = f"{s['phi_max']} (given); free fit {pm(free['phi_max'], free['phi_max_err'], 4)}"
        else:
            got = pm(s["phi_max"], s["phi_max_err"], 4)
        print(f"| {name} | {true_pm} | {got} | {s['phi_max_source']} | {pm(s['A'], s['A_err'])} | "
              f"{pm(s['alpha'], s['alpha_err'])} | {s['chi2_per_dof']:.2f} |")
    c = fits["collapse"]
    phi_max = ", ".join(f"{k}: {pm(v['value'], v['err'], 4)}" for k, v in c["phi_max"].items())
    print(f"| collapse | | {phi_max} | | {pm(c['A'], c['A_err'])} | "
          f"{pm(c['alpha'], c['alpha_err'])} | "
          f"{c['chi2_per_dof']:.2f} (rms {c['rms_log10_deviation']:.3f} decades) |")
    print()
    print("| sample | phi | n true | n recovered [95% interval] | error | regime | "
          "eta_N true / recovered [Pa s] | window [Pa] |")
    print("|---|---|---|---|---|---|---|---|")
    truth_of = {(c["sample"], c["phi"]): c for c in truth["curves"]}
    for r in rows:
        t = truth_of[(r["sample"], float(r["phi"]))]
        if t["n"] is None:
            n_true, got, err = "∞", f"{r['n']} ({r['dst_evidence']})", ""
        else:
            n_true = f"{t['n']:.3f}"
            got = f"{float(r['n']):.3f} [{float(r['n_low']):.3f}, {float(r['n_high']):.3f}]"
            err = f"{100 * (float(r['n']) / t['n'] - 1):+.1f}%"
        print(f"| {r['sample']} | {r['phi']} | {n_true} | {got} | {err} | {r['regime']} | "
              f"{t['eta_newtonian']:.3g} / {float(r['eta_newtonian']):.3g} | "
              f"{float(r['window_stress_low']):.3g}-{float(r['window_stress_high']):.3g} |")


if __name__ == "__main__":
    main()
