#!/usr/bin/env bash
# What the solver's stopping tolerance and its acceleration buy: the same points
# run at several solver.tolerance values, with the default sweeps (over-relaxed
# 1.3, "sor") and with the conjugate-gradient acceleration on plain sweeps
# ("cg"), each reporting the sweeps per step, the residual of the contact
# problem it leaves (solver/contact_residual.hpp) and the physics (eta, P_BL). Writes bench/results/tolerance-LABEL/<point>-<method>-<tol>/ and
# prints a markdown table (--report-only reprints it from the folders).
#
#   bash bench/tolerance_study.sh [--label L] [--binary PATH] [--jobs N] [--report-only]
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

source bench/lib.sh
parse_study_args "$0" "$@"
out=bench/results/tolerance-$label
mkdir -p "$out"

# The small-cell points of the solver issue (10 x 6 x 12 R, ~120 spheres).
small=(--set 'cell.size=[10.0, 6.0, 12.0]' --set run.strain=3.0 --set run.transient_strain=1.0
  --set run.snapshot_interval=0 --set solver.threads=1 --set solver.max_iterations=1000)
declare -A points=(
  [stribeck-mu0.3-lambda30]="--set friction.mu0=0.3 --set fluid.lambda=30"
  [stribeck-mu0.1-lambda100]="--set friction.mu0=0.1 --set fluid.lambda=100"
  [coulomb0.3-phi0.59]="--set friction.law=coulomb --set friction.mu0=0.3 --set cell.phi=0.59"
)
declare -A methods=(
  [sor]="--set solver.acceleration=none --set solver.relaxation=1.3"
  [cg]="--set solver.acceleration=cg --set solver.relaxation=1.0"
)
runs=()
for p in "${!points[@]}"; do
  for m in sor cg; do
    for tol in 1e-3 1e-4 1e-5; do runs+=("$p $m $tol"); done
  done
done
run_one() {
  local p m tol
  read -r p m tol <<<"$1"
  # shellcheck disable=SC2086
  "$binary" run "${small[@]}" ${points[$p]} ${methods[$m]} --set solver.tolerance="$tol" \
    --out "$out/$p-$m-$tol" -q 2>/dev/null || true
}
((report_only)) && runs=()
for r in "${runs[@]}"; do queue_run run_one "$r"; done
wait
# Keep what the table reads and what made it; the rest is large and reproducible.
find "$out" -type f ! -name summary.json ! -name config.toml -delete
python3 - "$out" <<'PY'
import json, pathlib, re, sys
rows = []
for d in sorted(pathlib.Path(sys.argv[1]).iterdir()):
    f = d / "summary.json"
    if not f.exists():
        continue
    s = json.loads(f.read_text())
    point, method, tol = re.fullmatch(r"(.*)-(sor|cg)-(.*)", d.name).groups()
    rows.append((point, method, float(tol), s))
print("| point | method | tolerance | sweeps / step | steps at the cap | residual max | residual rms | eta | P_BL | wall s / strain |")
print("|---|---|---|---|---|---|---|---|---|---|")
for point, method, tol, s in sorted(rows, key=lambda r: (r[0], r[1] != "sor", -r[2])):
    eta = "jammed" if s["jammed"] else f"{s['eta']:.4g} ± {s['eta_err']:.2g}"
    print(f"| {point} | {method} | {tol:.0e} | {s['mean_iterations']:.0f} | {s['frac_steps_unconverged']:.1%} | "
          f"{s['contact_residual_max']:.1e} | {s['contact_residual_rms']:.1e} | {eta} | "
          f"{s['frac_bl']:.3f} ± {s['frac_bl_err']:.3f} | {s['wall_time_per_strain_s']:.1f} |")
PY
