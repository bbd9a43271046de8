#!/usr/bin/python3
"""Synthetic stress-ramp flow curves with known answers, for `dilatant analyze`.

Writes, next to this script, the example of docs/analysis.md:
  manifest.toml        the four samples (coatings) A-D of the paper's Fig. 3, with
                       phi_max given for A and B (as if measured by centrifugation)
                       and left to the fit for C and D;
  A_*.csv ... D_*.txt  one flow curve per (sample, phi), in four file styles;
  truth.json           the values the curves were generated with;
and the realistic rheometer export tests/analysis/data/anton_paar_export.csv.

Run with Debian's python3 (needs numpy): /usr/bin/python3 examples/analysis/make_example.py
The output is fixed by the seed: re-running reproduces the committed files.

The model (in the variables of a stress-controlled ramp, stress tau imposed,
rate gamma_dot measured):
  ln gdot = ln(tau_c / eta_N) + F(u),  u = ln(tau / tau_c),
  F(u) = u - (1 - b)/m ln(1 + e^(m u)),  b = 1/(n + 1),  m = 2,
so gdot = tau/eta_N (Newtonian) well below tau_c and gdot ∝ tau^b, i.e.
eta ∝ gdot^n (Ostwald-de Waele), well above it; m sets the width of the
crossover (m = 2: about half a decade of stress). A DST curve has b < 0: above
tau_c the rate decreases slightly as the stress increases.
  n - 1 = A x^(-alpha), x = (phi_max - phi)/phi_max, A = 0.12, alpha = 0.9 for
every sample (the master curve); phi_max = 0.578, 0.560, 0.555, 0.545 (A-D,
the paper's values); eta_N = eta_s (1 - phi/0.64)^-2 with eta_s = 0.01 Pa s
(Krieger-Dougherty-like, independent of the coating, as in the paper's Fig. 3c).
The ramp descends from 700 to 0.01 Pa, 10 points per decade (as the paper's
Anton Paar ramp); the measured rate carries 2% log-normal noise.
"""
import json
from pathlib import Path

import numpy as np

SEED = 20130830  # the paper's publication date
HERE = Path(__file__).resolve().parent
TEST_DATA = HERE.parent.parent / "tests" / "analysis" / "data"

A_MASTER, ALPHA_MASTER = 0.12, 0.9
SAMPLES = {  # phi_max, onset stress tau_c [Pa], file style, phi_max in the manifest?
    "A": (0.578, 2.0, "csv", True),
    "B": (0.560, 3.0, "anton_paar_semicolon", True),
    "C": (0.555, 1.5, "tsv", False),
    "D": (0.545, 4.0, "anton_paar_tab", False),
}
REDUCED_FRACTIONS = [0.20, 0.12, 0.07, 0.04, 0.025, 0.015]  # x of the CST curves
DST_OFFSET = 0.006  # one DST curve per sample at phi_max + 0.006
DST_SLOPE = -0.03  # b of a DST curve: the rate falls slowly with stress
CROSSOVER_SHARPNESS = 2.0
NOISE = 0.02
ETA_SOLVENT, PHI_RCP = 0.01, 0.64
RAMP = np.geomspace(700.0, 0.01, 49)  # descending, 10 points per decade


def newtonian_viscosity(phi):
    return ETA_SOLVENT * (1.0 - phi / PHI_RCP) ** -2


def shear_rate(tau, eta_n, tau_c, b):
    u = np.log(tau / tau_c)
    m = CROSSOVER_SHARPNESS
    f = u - (1.0 - b) / m * np.logaddexp(0.0, m * u)
    return tau_c / eta_n * np.exp(f)


def onset_stress(tau_c, b, onset_factor=1.1):
    """Where eta = 1.1 eta_N: (1 + e^(m u))^((1-b)/m) = 1.1."""
    m = CROSSOVER_SHARPNESS
    return tau_c * (onset_factor ** (m / (1.0 - b)) - 1.0) ** (1.0 / m)


def sig(v, digits=5):
    return f"{v:.{digits}g}"


def comma(v, digits=5):
    return sig(v, digits).replace(".", ",")


def write_csv(path, tau, gdot):
    rows = ["Shear Rate (1/s),Shear Stress (Pa),Viscosity (Pa.s)"]
    rows += [f"{sig(g)},{sig(t)},{sig(t / g)}" for t, g in zip(tau, gdot)]
    path.write_text("\n".join(rows) + "\n")


def write_tsv(path, tau, gdot):
    rows = ["tau\tgamma_dot"]  # no units: SI
    rows += [f"{sig(t)}\t{sig(g)}" for t, g in zip(tau, gdot)]
    path.write_text("\n".join(rows) + "\n")


def anton_paar_lines(name, tau, gdot, sep, units_row):
    """Metadata, 'Interval data:' header, units row or units in the header, decimal commas."""
    lines = [
        f"Project:{sep}Quartz C400 in Ca(OH)2 buffer",
        f"Test:{sep}{name} stress ramp",
        f"Measuring system:{sep}ST22-4V-40 helical paddle",
        f"Interval and data points:{sep}1{sep}{len(tau)}",
        f"Profile:{sep}log stress ramp 700 Pa -> 0,01 Pa, 100 s",
        "",
    ]
    if units_row:
        lines.append(sep.join(["Interval data:", "Point No.", "Time", "Shear Rate", "Shear Stress",
                               "Viscosity", "Status"]))
        lines.append(sep.join(["", "", "[s]", "[1/s]", "[Pa]", "[mPa·s]", "[]"]))
    else:
        lines.append(sep.join(["Interval data:", "Point No.", "Time [s]", "Shear Rate [1/s]",
                               "Shear Stress [Pa]", "Viscosity [mPa·s]", "Status"]))
    for k, (t, g) in enumerate(zip(tau, gdot)):
        lines.append(sep.join(["", str(k + 1), comma((k + 1) * 100.0 / len(tau), 4), comma(g),
                               comma(t), comma(1e3 * t / g), "Dy_auto"]))
    return lines


def write_anton_paar(path, name, tau, gdot, sep, units_row):
    path.write_text("\n".join(anton_paar_lines(name, tau, gdot, sep, units_row)) + "\n",
                    encoding="utf-8")


def main():
    rng = np.random.default_rng(SEED)
    truth = {"seed": SEED, "A": A_MASTER, "alpha": ALPHA_MASTER, "noise": NOISE,
             "model": "n - 1 = A x^-alpha, x = (phi_max - phi)/phi_max", "samples": {},
             "curves": []}
    manifest = ["# Synthetic example of docs/analysis.md, written by make_example.py (seed "
                f"{SEED}).", "# phi_max of A and B given (as measured); C and D are fitted.", ""]
    for sample, (phi_max, tau_c, style, given) in SAMPLES.items():
        truth["samples"][sample] = {"phi_max": phi_max, "onset_scale_stress": tau_c}
        phis = [round(phi_max * (1.0 - x), 3) for x in REDUCED_FRACTIONS]
        phis.append(round(phi_max + DST_OFFSET, 3))
        for phi in phis:
            dst = phi > phi_max
            if dst:
                n, b = float("inf"), DST_SLOPE
            else:
                n = 1.0 + A_MASTER * ((phi_max - phi) / phi_max) ** -ALPHA_MASTER
                b = 1.0 / (n + 1.0)
            eta_n = newtonian_viscosity(phi)
            gdot = shear_rate(RAMP, eta_n, tau_c, b) * rng.lognormal(0.0, NOISE, RAMP.size)
            stem = f"{sample}_{round(phi * 1000):04d}"
            if style == "csv":
                name = stem + ".csv"
                write_csv(HERE / name, RAMP, gdot)
            elif style == "tsv":
                name = stem + ".tsv"
                write_tsv(HERE / name, RAMP, gdot)
            elif style == "anton_paar_semicolon":
                name = stem + ".csv"
                write_anton_paar(HERE / name, stem, RAMP, gdot, ";", units_row=False)
            else:
                name = stem + ".txt"
                write_anton_paar(HERE / name, stem, RAMP, gdot, "\t", units_row=True)
            truth["curves"].append({"sample": sample, "phi": phi, "file": name,
                                    "n": n if not dst else None, "regime": "dst" if dst else "cst",
                                    "eta_newtonian": eta_n,
                                    "onset_stress": onset_stress(tau_c, b)})
            manifest += ["[[curve]]", f'file = "{name}"', f'sample = "{sample}"', f"phi = {phi}",
                         ""]
    for sample, (phi_max, _, _, given) in SAMPLES.items():
        if given:
            manifest += [f"[samples.{sample}]", f"phi_max = {phi_max}", ""]
    (HERE / "manifest.toml").write_text("\n".join(manifest))
    (HERE / "truth.json").write_text(json.dumps(truth, indent=2) + "\n")

    # The test export: sample A at phi 0.537 with a little shear-thinning below
    # 0.05 Pa (as real suspensions show), Anton Paar style with ';' and a units row.
    phi, n = 0.537, 1.0 + A_MASTER * ((0.578 - 0.537) / 0.578) ** -ALPHA_MASTER
    gdot = shear_rate(RAMP, newtonian_viscosity(phi), 2.0, 1.0 / (n + 1.0))
    gdot /= 1.0 + 0.3 * np.exp(-np.log(RAMP / 0.01))  # eta up 30% at 0.01 Pa, 3% at 0.1 Pa
    gdot *= rng.lognormal(0.0, 0.01, RAMP.size)
    lines = anton_paar_lines("A_0537", RAMP, gdot, ";", units_row=True)
    lines.insert(5, f"Generator:;examples/analysis/make_example.py, seed {SEED}, n = {n:.4f}")
    TEST_DATA.mkdir(parents=True, exist_ok=True)
    (TEST_DATA / "anton_paar_export.csv").write_text("\n".join(lines) + "\n", encoding="utf-8")


if __name__ == "__main__":
    main()
