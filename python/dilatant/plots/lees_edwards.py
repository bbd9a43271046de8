"""Walls against Lees–Edwards at the same bulk fraction (issue 16; the paper's
supplement): Fig. 2's phi 0.58 curves (mu0 0.1, 0.4) and the DST map's boundary
ramps (mu0 1, 0.4; the 12 x 8 x 14 R and the paper's 25 x 10 x 27 R cells).

    PYTHONPATH=python python3 -m dilatant.plots.lees_edwards [DOCS]
                                               (default docs/paper-reproduction)

Reads DOCS/{fig2,lees-edwards-fig2,dst-map,dst-size,lees-edwards-dst}/flowcurves.csv
(scripts/docs-paper.sh copies them there) and writes DOCS/lees-edwards/:
comparison.csv (one row per wall/Lees–Edwards pair of points: eta, bulk
fraction, inertial number, P_BL, jammed) and comparison.png/.svg (eta against
lambda, walls filled, Lees–Edwards open; crosses mark jams). Points not run yet
are left out and counted: the script runs on partial sweeps.
"""
import csv
import math
import sys
from pathlib import Path

from .table_rows import number, read_rows

SMALL, PAPER = "12x8x14", "25x10x27"


def rows(path):
    if not path.is_file():
        print(f"dilatant.plots.lees_edwards: {path} not found (not run yet)", file=sys.stderr)
        return []
    return read_rows(path)


def point(row):
    """The measured numbers of one flow-curve row; None if it did not run."""
    if row.get("status") != "done":
        return None
    jammed = row.get("jammed") == "true"
    return {
        "eta": math.nan if jammed else number(row["eta"]),
        "eta_err": number(row.get("eta_err")),
        "phi_bulk": number(row["phi_bulk"]),
        "inertial_number": number(row.get("inertial_number")),
        "frac_bl": number(row.get("frac_bl")),
        "jammed": jammed,
        "cold_start": row.get("jam_cold_start", ""),
    }


def size_of(row, default):
    return row.get("cell.size", "").replace(" ", "").strip("[]").replace(".0", "").replace(",", "x") or default


def collect(docs):
    """(family, size, mu0, lambda) -> {"walls": point, "lees-edwards": point}."""
    pairs = {}

    def add(side, family, size, row):
        p = point(row)
        if p is None:
            return
        key = (family, size, number(row["mu0"]), number(row["lambda"]))
        pairs.setdefault(key, {})[side] = p

    for r in rows(docs / "fig2" / "flowcurves.csv"):
        if r["mu0"] in ("0.1", "0.4"):
            add("walls", "fig2", PAPER, r)
    for r in rows(docs / "lees-edwards-fig2" / "flowcurves.csv"):
        add("lees-edwards", "fig2", PAPER, r)
    # The map's phi 0.60 row is its boundary at phi_bulk ~0.58 (docs/paper-reproduction.md).
    for r in rows(docs / "dst-map" / "flowcurves.csv"):
        if r.get("cell.phi") in ("0.6", "0.60") and r["mu0"] in ("1", "0.4"):
            add("walls", "dst", SMALL, r)
    for r in rows(docs / "dst-size" / "flowcurves.csv"):
        add("walls", "dst", PAPER, r)
    for r in rows(docs / "lees-edwards-dst" / "flowcurves.csv"):
        add("lees-edwards", "dst", size_of(r, SMALL), r)
    return pairs


def write_table(pairs, out):
    fields = ["family", "size", "mu0", "lambda"]
    quantities = ["eta", "eta_err", "phi_bulk", "inertial_number", "frac_bl", "jammed"]
    for side in ("walls", "lees_edwards"):
        fields += [f"{q}_{side}" for q in quantities]
    fields.append("eta_ratio")  # Lees–Edwards over walls
    lines = []
    for key in sorted(pairs):
        both = pairs[key]
        w, le = both.get("walls"), both.get("lees-edwards")
        if w is None or le is None:
            continue
        row = dict(zip(["family", "size", "mu0", "lambda"], [key[0], key[1], f"{key[2]:g}", f"{key[3]:g}"]))
        for side, p in (("walls", w), ("lees_edwards", le)):
            for q in quantities:
                v = p[q]
                row[f"{q}_{side}"] = str(v).lower() if isinstance(v, bool) else f"{v:.5g}"
        ratio = le["eta"] / w["eta"]
        row["eta_ratio"] = f"{ratio:.3g}" if math.isfinite(ratio) else ""
        lines.append(row)
    tmp = out.with_suffix(".csv.part")
    with tmp.open("w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=fields)
        writer.writeheader()
        writer.writerows(lines)
    tmp.rename(out)
    return len(lines)


def plot(pairs, out_dir):
    # Imported here: the table above is written without matplotlib.
    from .common import plt, save

    panels = [("fig2", PAPER, "Fig. 2, phi 0.58, 25 x 10 x 27 R"),
              ("dst", SMALL, "DST boundary, 12 x 8 x 14 R"),
              ("dst", PAPER, "DST boundary, 25 x 10 x 27 R")]
    colours = {0.1: "tab:blue", 0.4: "tab:orange", 1.0: "tab:red"}
    fig, axes = plt.subplots(1, 3, figsize=(13, 4.2))
    for ax, (family, size, title) in zip(axes, panels):
        for mu0 in sorted({k[2] for k in pairs if k[0] == family and k[1] == size}):
            keys = sorted(k for k in pairs if k[:3] == (family, size, mu0))
            for side, marker, fill in (("walls", "o-", None), ("lees-edwards", "s--", "none")):
                pts = [(k[3], pairs[k][side]) for k in keys if side in pairs[k]]
                flowing = [(lam, p["eta"]) for lam, p in pts if not p["jammed"]]
                if flowing:
                    x, y = zip(*flowing)
                    ax.plot(x, y, marker, color=colours.get(mu0, "k"), mfc=fill,
                            label=f"mu0 {mu0:g}, {side}")
                for lam, p in pts:
                    if p["jammed"]:
                        top = max([e for _, e in flowing] or [1.0])
                        ax.plot(lam, top * 3, "x", color=colours.get(mu0, "k"), ms=10, mew=2)
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel("lambda (stress)")
        ax.set_title(title, fontsize=10)
        ax.legend(fontsize=7)
    axes[0].set_ylabel("eta / eta_f")
    fig.suptitle("Walls (filled) and Lees–Edwards (open) at phi_bulk 0.575-0.58; "
                 "x: jammed (drawn above the last flowing point)", fontsize=10)
    fig.tight_layout()
    save(fig, out_dir, "comparison", dpi=110, tight=False)


def main():
    docs = Path(sys.argv[1] if len(sys.argv) > 1 else "docs/paper-reproduction")
    out_dir = docs / "lees-edwards"
    out_dir.mkdir(parents=True, exist_ok=True)
    pairs = collect(docs)
    n = write_table(pairs, out_dir / "comparison.csv")
    unpaired = sum(1 for v in pairs.values() if len(v) < 2)
    print(f"dilatant.plots.lees_edwards: {n} pairs in {out_dir / 'comparison.csv'}"
          f"{f'; {unpaired} points without a counterpart (not run, or skipped after a jam)' if unpaired else ''}")
    plot(pairs, out_dir)


if __name__ == "__main__":
    main()
