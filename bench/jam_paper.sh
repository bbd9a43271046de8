#!/usr/bin/env bash
# Jams are jams, on the paper's cell: coulomb 0.3 at nominal phi 0.60
# (bench/configs/coulomb.toml with cell.phi = 0.60), the point that crept for
# 5,800 time units before the jam rule fired in an earlier record.
#
#   1. "run": a cold start at tolerance 1e-4 until the jam rule fires (less
#      than 1e-4 strain in 50 time units; drivers/shear_cell.hpp), with a row
#      every 5e-4 strain, so that the flow's history (avalanches, quiet
#      stretches) can be read; about 50 core-minutes.
#   2. "hold": from that jammed state (its checkpoint), the same cell under the
#      same stress at tolerances 1e-4, 1e-5 and 1e-6 (--start-from): how far
#      the held state creeps before the rule fires, against the tolerance.
#
#   bash bench/jam_paper.sh [--label L] [--binary PATH] [--jobs N] [--report-only]
#
# Keeps the summaries and time series under bench/results/jam-paper-LABEL/ and
# prints a table.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
source bench/lib.sh
parse_study_args "$0" "$@"
out=bench/results/jam-paper-$label
mkdir -p "$out"
point=(bench/configs/coulomb.toml --set cell.phi=0.60 --set solver.threads=1 -q)

if ((!report_only)); then
  "$binary" run "${point[@]}" --set run.strain=2 --set run.transient_strain=0.5 \
    --set run.output_interval=0.0005 --out "$out/run" 2>/dev/null || true
  hold() {
    "$binary" run "${point[@]}" --start-from "$out/run/checkpoint.bin" --set run.strain=0.02 \
      --set run.transient_strain=0.01 --set run.output_interval=0.000001 \
      --set solver.tolerance="$1" --set solver.max_iterations=5000 --out "$out/hold-$1" \
      2>/dev/null || true
  }
  for tol in 1e-4 1e-5 1e-6; do queue_run hold "$tol"; done
  wait
  # Keep what the table reads and what made it; the rest is large and reproducible.
  find "$out" -type f ! -name summary.json ! -name config.toml ! -name timeseries.csv -delete
fi

python3 - "$out" <<'PY'
import csv, json, pathlib, sys
out = pathlib.Path(sys.argv[1])
print("| run | tolerance | jammed at t | strain moved | strain in the last 50 time units | "
      "sweeps / step | sweep-equivalents / step | steps at the cap | residual max | wall s |")
print("|---|---|---|---|---|---|---|---|---|---|")
for d in sorted(out.iterdir()):
    if not (d / "summary.json").exists():
        continue
    s = json.loads((d / "summary.json").read_text())
    tol = json.dumps(None)
    for line in (d / "config.toml").read_text().splitlines():
        if line.startswith("tolerance"):
            tol = line.split("=")[1].strip()
    rows = list(csv.DictReader(open(d / "timeseries.csv")))
    t_end = float(rows[-1]["t"])
    before = [r for r in rows if float(r["t"]) <= t_end - 50.0]
    last = s["strain"] - (float(before[-1]["strain"]) if before else 0.0)
    print(f"| {d.name} | {tol} | {s['time']:.0f} | {s['strain']:.3g} | {last:.2g} | "
          f"{s['mean_iterations']:.0f} | {s.get('sweep_equivalents_per_step', s['mean_iterations']):.0f} | "
          f"{s['frac_steps_unconverged']:.1%} | {s['contact_residual_max']:.1e} | "
          f"{s['wall_time_s']:.0f} |")
PY
