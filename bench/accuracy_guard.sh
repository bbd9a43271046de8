#!/usr/bin/env bash
# Accuracy guard of the performance work (issue 4): eta with its block error bar
# on the viscous-side and the thickened (CST) point, run longer than the cost
# benchmark so that eta is resolved. (A jammed point is not included: at coulomb
# 0.3, phi 0.60-0.61 the cell creeps for thousands of time units before the jam
# rule fires, 11 minutes of run.) Compare the tables of two builds, or of
# one build at two tolerances:
#
#   bash bench/accuracy_guard.sh --label L [--binary PATH] [--strain 3] [-- --set solver.tolerance=5e-5]
#
# Keeps each summary.json under bench/results/accuracy-L/ and prints the table.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
label=""
binary=build/dilatant
strain=3.0
extra=()
while (($#)); do
  case "$1" in
    --label) label=$2; shift 2 ;;
    --binary) binary=$2; shift 2 ;;
    --strain) strain=$2; shift 2 ;;
    --) shift; extra=("$@"); break ;;
    *) echo "accuracy_guard.sh: unknown argument $1" >&2; exit 2 ;;
  esac
done
[[ -n "$label" ]] || { echo "accuracy_guard.sh: --label is required" >&2; exit 2; }
results="bench/results/accuracy-$label"
mkdir -p "$results"
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
# point name, config, overrides
run_point() {
  local name=$1 config=$2
  shift 2
  "$binary" run "bench/configs/$config.toml" --out "$scratch/$name" --quiet \
    --set "run.strain=$strain" --set run.transient_strain=1.0 "$@" "${extra[@]}" || true
  cp "$scratch/$name/summary.json" "$results/$name.json"
}
run_point viscous viscous
run_point thickened thickened
/usr/bin/env python3 - "$results" <<'PY'
import json, pathlib, sys
folder = pathlib.Path(sys.argv[1])
print(f"\n#### {folder.name}\n")
print("| point | eta | gamma_dot | frac_bl | jammed | sweeps/step | strain |")
print("|---|---|---|---|---|---|---|")
for p in sorted(folder.glob("*.json")):
    s = json.loads(p.read_text())
    eta = "null" if s["eta"] is None else f"{s['eta']:.4g} ± {s['eta_err']:.2g}"
    print(f"| {p.stem} | {eta} | {s['gamma_dot']:.4g} ± {s['gamma_dot_err']:.2g} | "
          f"{s['frac_bl']:.3f} | {s['jammed']} | {s['mean_iterations']:.0f} | {s['strain']:.2f} |")
PY
