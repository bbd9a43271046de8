#!/usr/bin/env bash
# Step problems of a run (the built-in default cell, or --config) solved again
# under other solver settings (docs/contact-solve-plan.md, "Step problems on disk"): dumps the
# states of 3 regular steps past the transient and of the first 3 steps that
# end at the pass cap (dilatant run --dump-steps), then solves each again with
# dilatant-solve-step under each setting below and keeps the tables, and runs
# the same 0.6 strain under each relaxation for the whole-run counts.
#
#   bash bench/step_problems.sh [--label L] [--config FILE --strain S --from S0]
#     (the default cell: about 2 minutes; the paper's cell, bench/configs/coulomb.toml
#      with --strain 0.5 --from 0.2: about 6)
#
# Writes bench/results/step-problems/LABEL/: index.csv (the dumped steps),
# solve-*.txt (one table a setting: passes, sweep-equivalents, the residual
# it ended with, the work to reach residual 1e-2 and 1e-3), and runs.txt. The
# dumped states themselves (~170 KB each) stay in a scratch folder.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
label=$(date +%Y%m%d) config=() strain=0.6 from=0.2
while (($#)); do
  case "$1" in
    --label) label=$2; shift 2 ;;
    --config) config=("$2"); shift 2 ;;
    --strain) strain=$2; shift 2 ;;
    --from) from=$2; shift 2 ;;
    *) echo "usage: step_problems.sh [--label L] [--config FILE --strain S --from S0]" >&2; exit 2 ;;
  esac
done
bash scripts/build.sh release dilatant dilatant-solve-step >/dev/null
results="bench/results/step-problems/$label"
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
mkdir -p "$results"
run=("${config[@]}" --quiet --set solver.threads=1 --set "run.strain=$strain"
  --set "run.transient_strain=$from")
build/dilatant run "${run[@]}" --out "$scratch/run" --dump-steps "$scratch/steps" \
  --dump-every 300 --dump-from-strain "$from" --dump-max 4 --dump-unconverged 3 2>/dev/null || true
cp "$scratch/steps/index.csv" "$results/index.csv"
declare -A settings=(
  [default]=""
  [relaxation-1.15]="--set solver.relaxation=1.15"
  [relaxation-1.0]="--set solver.relaxation=1.0"
  [no-skipping]="--set solver.skip_open_contacts=false"
  [plain-gs]="--set solver.relaxation=1.0 --set solver.skip_open_contacts=false"
  [cg]="--set solver.acceleration=\"cg\"")
for name in "${!settings[@]}"; do
  eval build/bench/dilatant-solve-step "$scratch/steps" ${settings[$name]} --targets 1e-2,1e-3 \
    | column -t >"$results/solve-$name.txt"
done
{
  echo "${config[*]:-built-in default} run, $strain strain, per solver.relaxation (one seed, one thread)"
  for w in 1.3 1.15 1.0; do
    build/dilatant run "${run[@]}" --out "$scratch/w$w" --set "solver.relaxation=$w" 2>/dev/null
    python3 - "$scratch/w$w/summary.json" "$w" <<'PY'
import json, sys
j = json.load(open(sys.argv[1]))
print(f"relaxation {sys.argv[2]}: {j['steps']} steps, "
      f"{round(j['frac_steps_unconverged'] * j['steps'])} at the pass cap, "
      f"{j['sweep_equivalents_per_step']:.1f} sweep-equivalents / step, "
      f"contact_residual_max {j['contact_residual_max']:.3g}, eta {j['eta']:.4g}")
PY
  done
  echo "commit: $(git rev-parse --short HEAD); $(date -u +%Y-%m-%dT%H:%MZ)"
} >"$results/runs.txt"
cat "$results/runs.txt"
