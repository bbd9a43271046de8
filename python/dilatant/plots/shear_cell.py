"""Figures and a table for docs/shear-cell.md from shear-cell run folders.

Usage: PYTHONPATH=python python3 -m dilatant.plots.shear_cell OUT_DIR \\
           LABEL=RUN_DIR [LABEL=RUN_DIR ...]
Writes OUT_DIR/profiles.{png,svg}, OUT_DIR/sommerfeld.{png,svg},
OUT_DIR/timeseries.{png,svg} and OUT_DIR/table.md (numbers from summary.json).
Needs Debian's python3-matplotlib and python3-numpy.
"""
import csv
import json
import math
import sys
from pathlib import Path

from .common import plt, save

import numpy as np


def read_csv(path):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    return {k: np.array([float(r[k]) if r[k] != "inf" else math.inf for r in rows]) for k in rows[0]}


def read_toml_value(path, section, key):
    current = None
    for line in Path(path).read_text().splitlines():
        line = line.split("#")[0].strip()
        if line.startswith("["):
            current = line.strip("[]")
        elif current == section and line.startswith(key + " "):
            return line.split("=", 1)[1].strip()
    return None


def mu_stribeck(s, mu0, s_c, s_lim):
    s_eff = np.minimum(s, s_lim)
    hd = 2 * np.pi * s_eff * np.log(5 / (6 * np.pi * s_eff))
    return np.where(s < s_c, mu0, hd)


def main():
    out = Path(sys.argv[1])
    out.mkdir(parents=True, exist_ok=True)
    runs = [arg.split("=", 1) for arg in sys.argv[2:]]

    fig_p, ax_p = plt.subplots(figsize=(4.5, 4))
    fig_s, ax_s = plt.subplots(figsize=(5.5, 4))
    fig_t, ax_t = plt.subplots(figsize=(5.5, 3.5))
    table = ["| run | lambda | gamma_dot | gamma_dot_gap | gamma_dot_bulk | eta | P_BL | "
             "beyond s_lim | phi | phi_bulk | I | valid | strain | steps | wall time |",
             "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
    mu0 = s_c = s_lim = None
    versions = set()
    for label, folder in runs:
        folder = Path(folder)
        summary = json.loads((folder / "summary.json").read_text())
        lz = float(read_toml_value(folder / "config.toml", "cell", "size").strip("[]").split(",")[2])
        prof = read_csv(folder / "velocity_profile.csv")
        v_wall = summary.get("wall_velocity", summary["gamma_dot"] / summary["lambda"] * lz)
        if not summary["jammed"] and v_wall > 0:
            ax_p.plot(prof["vx"] / v_wall, prof["z"] / lz, "o-", ms=3, label=label)
        hist = read_csv(folder / "sommerfeld_hist.csv")
        sliding = hist["s_high"] > 0
        lo, hi = hist["s_low"][sliding], hist["s_high"][sliding]
        finite = np.isfinite(hi) & (lo > 0)
        centres = np.sqrt(lo[finite] * hi[finite])
        ax_s.step(centres, hist["fraction"][sliding][finite], where="mid",
                  label=f"{label} (stick {hist['fraction'][0]:.2f})")
        ts = read_csv(folder / "timeseries.csv")
        ax_t.plot(ts["strain"], ts["gamma_dot"] * summary["lambda"], lw=0.8, label=label)
        mu0, s_c, s_lim = summary["mu0"], summary["s_c"], summary["s_lim"]
        versions.add(summary["version"])
        f = lambda key, d=3: f"{summary[key]:.{d}g}"  # noqa: E731
        table.append(
            f"| {label} | {f('lambda')} | {f('gamma_dot')} ± {summary['gamma_dot_err']:.2g} | "
            f"{summary.get('gamma_dot_gap', math.nan):.3g} | {f('gamma_dot_bulk')} | "
            + (f"{summary['eta']:.3g} ± {summary['eta_err']:.2g}" if not summary["jammed"]
               else "jammed") + f" | {f('frac_bl')} | "
            f"{f('frac_over_slim')} | {f('phi', 4)} | {f('phi_bulk', 4)} | "
            f"{f('inertial_number')} | {summary['valid']} | {f('strain')} | {summary['steps']} | "
            f"{summary['wall_time_s']:.0f} s |")
    zz = np.linspace(0, 1, 2)
    ax_p.plot(zz, zz, "k--", lw=0.8, label="linear, V z / Lz")
    ax_p.set_xlabel(r"$v_x / \langle v_{wall} \rangle$")
    ax_p.set_ylabel(r"$z / L_z$")
    ax_p.legend(fontsize=8)
    fig_p.tight_layout()
    ax_s.set_xscale("log")
    ax_s.set_xlabel("Sommerfeld number $s$")
    ax_s.set_ylabel("fraction of sliding contacts per bin")
    ax_s.axvline(s_c, color="gray", lw=0.8, ls=":")
    ax_s.axvline(s_lim, color="gray", lw=0.8, ls=":")
    ax_mu = ax_s.twinx()
    ss = np.logspace(-8, 1, 400)
    ax_mu.plot(ss, mu_stribeck(ss, mu0, s_c, s_lim), "k-", lw=1, label=r"$\mu(s)$")
    ax_mu.set_ylabel(r"friction law $\mu(s)$")
    ax_s.legend(fontsize=8, loc="upper left")
    fig_s.tight_layout()
    ax_t.set_xlabel("strain")
    ax_t.set_ylabel(r"$\dot\gamma$ [$\eta_f/(\rho_p R^2)$]")
    ax_t.set_yscale("log")
    ax_t.legend(fontsize=8)
    fig_t.tight_layout()
    for name, fig in (("profiles", fig_p), ("sommerfeld", fig_s), ("timeseries", fig_t)):
        save(fig, out, name, dpi=130, tight=False)
    table.append("")
    table.append(f"Made by dilatant {', '.join(sorted(versions))}; the settings of each run are "
                 "its config.toml (see scripts/docs-shear-cell.sh).")
    (out / "table.md").write_text("\n".join(table) + "\n")


if __name__ == "__main__":
    main()
