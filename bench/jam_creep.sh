#!/usr/bin/env bash
# Does a jammed packing creep because the solver stops early? A packing above
# its jamming fraction under a stress it can hold is run under several stopping
# tests (solver.convergence, docs/model.md "Convergence criterion"): the
# load-scaled residual at several tolerances, and the relative change of one
# sweep at 1e-4 (the test before 0.7), with the default sweeps ("sor") and the
# conjugate-gradient acceleration ("cg"); for each: when the jam rule fired
# (drivers/shear_cell.hpp: less than 1e-4 strain in 50 time units), the strain
# crept before, and the creep rate over the last output rows. Writes
# bench/results/jam-LABEL/ (the summaries and time series) and prints a
# markdown table.
#
#   bash bench/jam_creep.sh [--label L] [--binary PATH] [--jobs N] [--report-only]
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

source bench/lib.sh
parse_study_args "$0" "$@"
out=bench/results/jam-$label
mkdir -p "$out"

# 15 x 10 x 18 R (~470 spheres), coulomb mu0 1.0 at phi 0.60: jams (issue 14's measurement).
cell=(--set 'cell.size=[15.0, 10.0, 18.0]' --set cell.phi=0.60 --set friction.law=coulomb
  --set friction.mu0=1.0 --set run.strain=2 --set run.transient_strain=0.5
  --set run.snapshot_interval=0 --set run.output_interval=0.0005 --set solver.threads=1)
declare -A methods=(
  [sor]="--set solver.acceleration=none --set solver.relaxation=1.3"
  [cg]="--set solver.acceleration=cg --set solver.relaxation=1.0"
)
runs=()
if ((!report_only)); then
  for m in sor cg; do
    runs+=("$m change 1e-4")
    for tol in 3e-2 1e-2 3e-3; do runs+=("$m residual $tol"); done
  done
fi
run_one() {
  local m test tol
  read -r m test tol <<<"$1"
  # shellcheck disable=SC2086
  nice "$binary" run "${cell[@]}" ${methods[$m]} --set solver.convergence="$test" \
    --set solver.tolerance="$tol" --out "$out/$m-$test-$tol" -q 2>/dev/null
}
for r in "${runs[@]}"; do queue_run run_one "$r"; done
wait
find "$out" -type f ! -name summary.json ! -name config.toml ! -name timeseries.csv -delete
python3 - "$out" <<'PY'
import csv, json, pathlib, re, sys
print("| method | test | tolerance | jammed | at t | strain crept | creep rate, t 10 to jam - 50 | sweeps / step | steps at the cap | residual max (P_ref) | wall s |")
print("|---|---|---|---|---|---|---|---|---|---|---|")
rows = []
for d in sorted(pathlib.Path(sys.argv[1]).iterdir()):
    if not (d / "summary.json").exists():
        continue
    m, test, tol = re.fullmatch(r"(sor|cg)-(residual|change)-(.*)", d.name).groups()
    s = json.loads((d / "summary.json").read_text())
    series = list(csv.DictReader(open(d / "timeseries.csv")))
    # Creep before the jam was declared: from t = 10 (after the first
    # compaction) to the start of the last 50-time-unit window (which the rule
    # judged to be still), by the rows nearest those times.
    t_end = float(series[-1]["t"])
    def at(t):
        return min(series, key=lambda r: abs(float(r["t"]) - t))
    a, b = at(10.0), at(t_end - 50.0)
    dt = float(b["t"]) - float(a["t"])
    rate = (float(b["strain"]) - float(a["strain"])) / dt if dt > 5.0 else None
    rows.append((m, test, float(tol), s, rate))
for m, test, tol, s, rate in sorted(rows, key=lambda r: (r[0] != "sor", r[1], -r[2])):
    creep = "< 5e-4 strain in all" if rate is None else f"{rate:.1e}"
    print(f"| {m} | {test} | {tol:.0e} | {'yes' if s['jammed'] else 'no'} | {s['time']:.0f} | {s['strain']:.4f} | {creep} | "
          f"{s['mean_iterations']:.0f} | {s['frac_steps_unconverged']:.1%} | "
          f"{s['contact_residual_max']:.1e} | {s['wall_time_s']:.0f} |")
PY
