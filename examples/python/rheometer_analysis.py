#!/usr/bin/python3
"""Rheometer files analysed from Python (docs/analysis.md): the shipped
synthetic example (four samples, 28 stress ramps in CSV, TSV and text
exports) through dilatant.analyze, then n(phi) of each sample drawn from the
returned tables, with the fitted divergence n - 1 = A x^-alpha.

    PYTHONPATH=build/python python3 examples/python/rheometer_analysis.py --out out/py-analysis
    ... MANIFEST     your own manifest (see examples/analysis/manifest.toml)

Seconds; CI runs it as is.
"""
import argparse
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import dilatant  # noqa: E402

HERE = Path(__file__).resolve().parent


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("manifest", nargs="?", type=Path,
                        default=HERE.parent / "analysis" / "manifest.toml")
    parser.add_argument("--out", type=Path, default=Path("out/py-analysis"))
    args = parser.parse_args()

    # The CLI's analysis and figures (flow_curves, n_vs_phi, collapse) into --out ...
    result = dilatant.analyze(args.manifest, args.out)
    curves = result.curves
    print(f"{len(curves)} curves; regimes: "
          + ", ".join(f"{r} {np.sum(curves['regime'] == r)}" for r in np.unique(curves["regime"])))

    # ... and a figure of our own from the returned arrays.
    fig, ax = plt.subplots(figsize=(5, 4))
    for sample, fit in result.fits["samples"].items():
        mine = curves[(curves["sample"] == sample) & (curves["regime"] == "cst")]
        line = ax.errorbar(mine["phi"], mine["n"], yerr=[mine["n"] - mine["n_low"],
                           mine["n_high"] - mine["n"]], marker="o", ls="none", label=sample)
        if fit.get("A") is not None:  # the fit n - 1 = A x^-alpha, x = (phi_max - phi)/phi_max
            phi_max, a, alpha = fit["phi_max"], fit["A"], fit["alpha"]
            phi = np.linspace(mine["phi"].min() * 0.98, phi_max * 0.995, 100)
            ax.plot(phi, 1 + a * ((phi_max - phi) / phi_max) ** -alpha, color=line[0].get_color())
            print(f"sample {sample}: phi_max {phi_max:.4f} ({fit['phi_max_source']}), "
                  f"A {a:.3g}, alpha {alpha:.3g}")
    ax.set_yscale("log")
    ax.set_xlabel(r"$\phi$")
    ax.set_ylabel(r"Ostwald-de Waele exponent $n$")
    ax.legend(title="sample")
    fig.savefig(args.out / "n_of_phi_from_python.png", dpi=120, bbox_inches="tight")
    print(f"results and figures in {args.out}")


if __name__ == "__main__":
    main()
