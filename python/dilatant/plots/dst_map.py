"""The DST map of docs/paper-reproduction.md (issue 15): every stress ramp of
a `dilatant sweep` with continuation placed at its (mu0, phi_bulk) and marked
by what it did, over the jamming fractions of docs/jamming.md (the paper's
Fig. 4 with simulations on it).

  PYTHONPATH=python python3 -m dilatant.plots.dst_map DOCS NAME SWEEP[=CELL] [SWEEP[=CELL] ...]
    CELL labels a sweep run in another cell than the map's (e.g.
    dst-size=25x10x27): its ramps are drawn as large open markers.
    reads  SWEEP/flowcurves.csv           the ramps (examples/paper/dst-map.toml,
                                          dst-map-mu0.toml)
           data/jamming/phi_max_bl.csv    the sediment phi_max_BL(mu0)
           docs/jamming/shear_jamming.csv the shear-jamming brackets (optional)
    writes DOCS/NAME.csv  one row per ramp: mu0, nominal phi, phi_bulk (mean
                          over its flowing points, else its jammed ones),
                          outcome, the first jammed lambda, the cold start's
                          verdict, the largest lambda that flowed, eta there
           DOCS/NAME.png/.svg  the map

Outcomes: `dst` the ramp flows at low stress and jams above (the jam's cold
start said `jammed`), `dst?` the same but the cold start flowed or is missing,
`jammed` no point flowed, `flows` no point jammed (CST or Newtonian over the
ramp's range), `running` the ramp has not finished and has not jammed.
"""
import csv
import os
import sys
from collections import defaultdict
from pathlib import Path

from .common import plt, read_rows, save


def source_tree():
    """The checkout that holds data/jamming/ (this file is python/dilatant/plots/ in
    it, or a copy in <build>/python/dilatant/plots/); else the working folder."""
    for folder in Path(__file__).resolve().parents:
        if (folder / "data" / "jamming" / "phi_max_bl.csv").is_file():
            return folder
    return Path.cwd()


ROOT = source_tree()
MARKERS = {"dst": ("v", "tab:red"), "dst?": ("v", "tab:orange"), "jammed": ("x", "k"),
           "flows": ("o", "tab:blue")}


def ramps(rows):
    groups = defaultdict(list)
    for r in rows:
        groups[(r.get("cell", ""), float(r["mu0"]), float(r["phi"]), r["sample"])].append(r)
    out = []
    for (cell, mu0, phi, sample), points in sorted(groups.items()):
        points.sort(key=lambda r: float(r["lambda"]))
        done = [r for r in points if r["status"] == "done"]
        flowing = [r for r in done if r["jammed"] == "false"]
        jams = [r for r in done if r["jammed"] == "true"]
        unfinished = any(r["status"] == "pending" for r in points)
        if not done or (unfinished and not jams):
            outcome = "running"
        elif not flowing:
            outcome = "jammed"
        elif jams:
            outcome = "dst" if jams[0]["jam_cold_start"] == "jammed" else "dst?"
        else:
            outcome = "flows"
        source = flowing or jams
        out.append({
            "mu0": mu0, "phi": phi, "sample": sample, "cell": cell,
            "phi_bulk": (sum(float(r["phi_bulk"]) for r in source) / len(source)
                         if source else None),
            "outcome": outcome,
            "jam_lambda": jams[0]["lambda"] if jams else "",
            "jam_cold_start": jams[0]["jam_cold_start"] if jams else "",
            "top_flowing_lambda": flowing[-1]["lambda"] if flowing else "",
            "top_flowing_eta": flowing[-1]["eta"] if flowing else "",
            "points_done": len(done), "points": len(points),
        })
    return out


def write_table(entries, path):
    part = path.with_name(path.name + ".part")
    with open(part, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(entries[0].keys()))
        w.writeheader()
        for e in entries:
            w.writerow({k: (f"{v:.4f}" if k == "phi_bulk" and v is not None else v)
                        for k, v in e.items()})
    os.replace(part, path)


def draw(entries, docs, name):
    table = read_rows(ROOT / "data" / "jamming" / "phi_max_bl.csv")
    mu = [float(r["mu0"]) for r in table]
    phi = [float(r["phi_max"]) for r in table]
    err = [float(r["phi_max_err"] or 0) for r in table]
    fig, ax = plt.subplots(figsize=(7.5, 4))
    ax.fill_between(mu, phi, [0.50] * len(mu), color="tab:blue", alpha=0.10)
    ax.fill_between(mu, phi, [phi[0]] * len(mu), color="tab:red", alpha=0.10)
    ax.errorbar(mu, phi, yerr=err, color="k", marker=".", capsize=2, lw=1,
                label=r"sediment $\phi_{max}^{BL}$ (dilatant jam)")
    shear = ROOT / "docs" / "jamming" / "shear_jamming.csv"
    if shear.exists():
        for r in read_rows(shear):
            if r["phi_bulk_flowing_max"] and r["phi_bulk_jammed_min"]:
                ax.plot([float(r["mu0"])] * 2, [float(r["phi_bulk_flowing_max"]),
                                                float(r["phi_bulk_jammed_min"])],
                        color="tab:green", lw=4, alpha=0.35)
        ax.plot([], [], color="tab:green", lw=4, alpha=0.35, label="dry shear jamming bracket")
    for outcome, (marker, colour) in MARKERS.items():
        for cell in sorted({e["cell"] for e in entries}):
            chosen = [e for e in entries if e["outcome"] == outcome and e["cell"] == cell
                      and e["phi_bulk"] is not None]
            if not chosen:
                continue
            style = (dict(s=40, color=colour) if not cell else
                     dict(s=110, facecolors="none", edgecolors=colour, linewidths=1.5))
            ax.scatter([e["mu0"] for e in chosen], [e["phi_bulk"] for e in chosen], marker=marker,
                       zorder=3, label=f"ramp: {outcome}" + (f" ({cell} cell)" if cell else ""),
                       **style)
    ax.set_xlabel(r"boundary friction $\mu_0$")
    ax.set_ylabel(r"$\phi_{bulk}$")
    ax.set_ylim(0.54, 0.645)
    ax.set_title("stress ramps to the jam over phi_max_BL(mu0); filled: 12 x 8 x 14 R cell",
                 fontsize=9)
    ax.legend(fontsize=7, loc="upper left", bbox_to_anchor=(1.01, 1.0))
    fig.tight_layout()
    save(fig, docs, name)


def main(argv):
    if len(argv) < 4:
        sys.exit(__doc__)
    docs, name = Path(argv[1]), argv[2]
    rows = []
    for arg in argv[3:]:
        sweep, _, cell = arg.partition("=")
        rows += [dict(r, cell=cell) for r in read_rows(Path(sweep) / "flowcurves.csv")]
    entries = ramps(rows)
    docs.mkdir(parents=True, exist_ok=True)
    write_table(entries, docs / f"{name}.csv")
    draw(entries, docs, name)
    for e in entries:
        print(f"mu0 {e['mu0']} phi {e['phi']}{' (' + e['cell'] + ')' if e['cell'] else ''}: "
              f"phi_bulk {e['phi_bulk']}, {e['outcome']}"
              f"{' at lambda ' + e['jam_lambda'] if e['jam_lambda'] else ''}")


if __name__ == "__main__":
    main(sys.argv)
