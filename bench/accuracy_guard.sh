#!/usr/bin/env bash
# Accuracy guard of the performance work: eta and P_BL on the viscous-side and
# the thickened (CST) point of the paper's cell, averaged over seeds, so that a
# change of method is judged against the seed-to-seed scatter (a single run's
# block error understates it about 2x on small cells). Run two labels (two
# builds, or one build with two settings) and compare them:
#
#   bash bench/accuracy_guard.sh --label L [--binary PATH] [--strain 3] [--seeds "1 2 3 4"]
#                                [--jobs 1] [-- --set solver.acceleration=cg ...]
#   bash bench/accuracy_guard.sh --compare LABEL_A LABEL_B
#
# Keeps each run's summary.json as bench/results/accuracy-L/POINT-sSEED.json and
# prints, per point, the seed mean and its standard error (for eta and P_BL at
# least the one the runs' own block errors give); --compare prints the
# difference of the means in units of their combined standard error.
# (A jammed point is not included: bench/jam_creep.sh measures jams.)
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
label=""
binary=build/dilatant
strain=3.0
seeds="1 2 3 4"
jobs=1
extra=()
compare=()
while (($#)); do
  case "$1" in
    --label) label=$2; shift 2 ;;
    --binary) binary=$2; shift 2 ;;
    --strain) strain=$2; shift 2 ;;
    --seeds) seeds=$2; shift 2 ;;
    --jobs) jobs=$2; shift 2 ;;
    --compare) compare=("$2" "$3"); shift 3 ;;
    --) shift; extra=("$@"); break ;;
    *) echo "accuracy_guard.sh: unknown argument $1" >&2; exit 2 ;;
  esac
done

if ((${#compare[@]} == 0)); then
  [[ -n "$label" ]] || { echo "accuracy_guard.sh: --label is required" >&2; exit 2; }
  source bench/lib.sh
  results="bench/results/accuracy-$label"
  mkdir -p "$results"
  scratch=$(mktemp -d)
  trap 'rm -rf "$scratch"' EXIT
  run_point() {  # run_point POINT SEED
    local name="$1-s$2"
    [[ -f "$results/$name.json" ]] && return 0  # resumable: a finished run is kept
    "$binary" run "bench/configs/$1.toml" --out "$scratch/$name" --quiet \
      --set "run.strain=$strain" --set run.transient_strain=1.0 --set "cell.seed=$2" \
      --set solver.threads=1 "${extra[@]}" || true
    cp "$scratch/$name/summary.json" "$results/$name.json.part" &&
      mv "$results/$name.json.part" "$results/$name.json"
    cp "$scratch/$name/config.toml" "$results/$name.toml"
  }
  for seed in $seeds; do
    for point in viscous thickened; do queue_run run_point "$point" "$seed"; done
  done
  wait
  compare=("$label")
fi

/usr/bin/env python3 - "${compare[@]}" <<'PY'
import json, math, pathlib, re, statistics, sys
def load(label):
    points = {}
    for p in sorted(pathlib.Path(f"bench/results/accuracy-{label}").glob("*-s*.json")):
        point = re.fullmatch(r"(.*)-s\d+", p.stem).group(1)
        points.setdefault(point, []).append(json.loads(p.read_text()))
    return points
def mean_sem(values, errors=None):
    """Seed mean and its standard error. With each run's own (block) error, the
    error is at least what those give, sqrt(sum err^2) / n: four seeds that
    happen to agree closely must not make their mean look sharper than the runs."""
    m = statistics.fmean(values)
    sem = statistics.stdev(values) / math.sqrt(len(values)) if len(values) > 1 else math.nan
    if errors:
        sem = max(sem, math.sqrt(sum(e * e for e in errors)) / len(errors))
    return m, sem
ERRORS = {"eta": "eta_err", "frac_bl": "frac_bl_err"}
def stats(runs, key):
    errors = [r[ERRORS[key]] for r in runs] if key in ERRORS else None
    return mean_sem([value(r, key) for r in runs], errors)
keys = [("eta", "eta"), ("P_BL", "frac_bl"), ("sweeps/step", "mean_iterations"),
        ("sweep-equivalents/step", "sweep_equivalents_per_step"),
        ("residual max", "contact_residual_max"), ("wall s/strain", "wall_time_per_strain_s")]
def value(run, key):
    # Runs made before sweep_equivalents_per_step existed visited every contact in every sweep.
    return run.get(key, run["mean_iterations"] if key == "sweep_equivalents_per_step" else None)
tables = {label: load(label) for label in sys.argv[1:]}
print("| label | point | seeds | " + " | ".join(k for k, _ in keys) + " |")
print("|---|---|---|" + "---|" * len(keys))
for label, points in tables.items():
    for point, runs in sorted(points.items()):
        cells = []
        for _, key in keys:
            m, e = stats(runs, key)
            cells.append(f"{m:.4g} ± {e:.2g}")
        print(f"| {label} | {point} | {len(runs)} | " + " | ".join(cells) + " |")
if len(tables) == 2:
    (la, a), (lb, b) = tables.items()
    print(f"\n{lb} against {la}: difference of the seed means / combined standard error")
    for point in sorted(set(a) & set(b)):
        parts = []
        for name, key in keys[:2]:
            ma, ea = stats(a[point], key)
            mb, eb = stats(b[point], key)
            parts.append(f"{name} {mb - ma:+.4g} ({(mb - ma) / math.hypot(ea, eb):+.1f} sigma)")
        print(f"- {point}: " + ", ".join(parts))
PY
