"""Markdown table of a whole-run benchmark folder (bench/whole_run.sh).

    python3 bench/report.py bench/results/LABEL [more folders...]

Standard library only. One row per point and thread count: cost per unit
strain, its split by stage, the solver's work, and eta with its error bar
(the accuracy guard). Older builds lack some keys: those cells read '-'.
"""
import json
import pathlib
import sys

COLUMNS = [
    ("point", None),
    ("threads", "threads"),
    ("wall s/strain", "wall_time_per_strain_s"),
    ("steps/strain", "steps_per_strain"),
    ("sweeps/step", "mean_iterations"),
    ("sweep-equivalents/step", "sweep_equivalents_per_step"),
    ("ns/contact update", "ns_per_contact_update"),
    ("solve %", "solve"),
    ("detect %", "detection"),
    ("measure %", "measure"),
    ("peak MiB", "peak_memory_mib"),
    ("eta", "eta"),
    ("I", "inertial_number"),
]


def cell(summary, key):
    if key in ("solve", "detection", "measure"):
        total = summary.get("wall_s_run")
        part = summary.get(f"time_{key}_s")
        return "-" if part is None or not total else f"{100 * part / total:.0f}"
    value = summary.get(key)
    if key == "sweep_equivalents_per_step" and value is None:
        value = summary.get("mean_iterations")  # before skipping: every sweep was full
    if key == "eta":
        if value is None:
            return "jammed" if summary.get("jammed") else "-"
        return f"{value:.4g} ± {summary.get('eta_err', 0):.2g}"
    if key == "wall_time_per_strain_s" and value is None:
        # Builds before the cost keys: whole wall time over the strain run.
        value = summary["wall_time_s"] / summary["strain"]
    if value is None:
        return "-"
    return f"{value:.3g}" if isinstance(value, float) else str(value)


def main(folders):
    for folder in map(pathlib.Path, folders):
        print(f"\n#### {folder.name}\n")
        machine = folder / "machine.txt"
        if machine.exists():
            print("\n".join(f"    {line}" for line in machine.read_text().splitlines()) + "\n")
        print("| " + " | ".join(name for name, _ in COLUMNS) + " |")
        print("|" + "---|" * len(COLUMNS))
        for path in sorted(folder.glob("*.json")):
            s = json.loads(path.read_text())
            s["wall_s_run"] = s["wall_time_s"] - s.get("time_build_s", 0.0)
            point = path.stem.rsplit("-t", 1)[0]
            row = [point] + [cell(s, key) for _, key in COLUMNS[1:]]
            if COLUMNS[1][1] not in s:
                row[1] = path.stem.rsplit("-t", 1)[1] + " (unset)"
            print("| " + " | ".join(row) + " |")


if __name__ == "__main__":
    main(sys.argv[1:])
