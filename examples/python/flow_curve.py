#!/usr/bin/python3
"""One flow curve of the paper's shear cell, end to end from Python: a run per
stress (lambda = sqrt(tau rho_p) R / eta_f, the paper's stress axis), the
steady viscosity of each, and the curve eta(gamma_dot) drawn.

    PYTHONPATH=build/python python3 examples/python/flow_curve.py --out out/py-flow-curve
    ... --small      a 6 x 5 x 7 R cell for seconds (what CI runs)

Default: a 12 x 8 x 14 R cell (217 spheres, phi 0.58, mu0 0.1, the literal
model) at five stresses, 4 strain units each: about ten minutes on one core.
The same curve as a sweep file: examples/sweep/continuation-check.toml.
"""
import argparse
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

import dilatant  # noqa: E402


def cell(small):
    if small:
        return {"cell": {"size": [6.0, 5.0, 7.0], "phi": 0.58},
                "run": {"strain": 0.2, "transient_strain": 0.1, "snapshot_interval": 0.0}}
    return {"cell": {"size": [12.0, 8.0, 14.0], "phi": 0.58},
            "friction": {"mu0": 0.1},
            "run": {"strain": 4.0, "transient_strain": 2.0, "snapshot_interval": 0.0}}


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", type=Path, default=Path("out/py-flow-curve"))
    parser.add_argument("--small", action="store_true", help="a tiny cell, for CI")
    args = parser.parse_args()
    lambdas = [10.0, 100.0] if args.small else [10.0, 20.0, 50.0, 100.0, 200.0]

    points = []
    for lam in lambdas:
        config = cell(args.small)
        config["fluid"] = {"lambda": lam}
        result = dilatant.run(config, out=args.out / f"lambda={lam:g}",
                              progress=lambda f: print(f"\rlambda {lam:g}: {100 * f:3.0f}%",
                                                       end="", flush=True))
        s = result.summary
        print(f"\rlambda {lam:g}: gamma_dot {s['gamma_dot']:.4g}, eta {s['eta']:.4g} "
              f"+- {s['eta_err']:.2g} eta_f, P_BL {s['frac_bl']:.3f}, valid {s['valid']}")
        points.append((s["gamma_dot"], s["eta"], s["eta_err"], s["valid"]))

    fig, ax = plt.subplots(figsize=(5, 4))
    rate, eta, err, valid = zip(*points)
    ax.errorbar(rate, eta, yerr=err, marker="o", capsize=3)
    for r, e, ok in zip(rate, eta, valid):
        if not ok:  # outside the model's validity: hollow grey, never a result
            ax.plot(r, e, "o", mfc="none", color="0.6")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel(r"shear rate $\dot\gamma$ [$\eta_f/(\rho_p R^2)$]")
    ax.set_ylabel(r"viscosity $\eta$ [$\eta_f$]")
    ax.set_title(f"flow curve, phi 0.58, mu0 0.1 (dilatant {dilatant.__version__})", fontsize=9)
    args.out.mkdir(parents=True, exist_ok=True)
    fig.savefig(args.out / "flow_curve.png", dpi=120, bbox_inches="tight")
    print(f"figure: {args.out / 'flow_curve.png'}")


if __name__ == "__main__":
    main()
