#!/usr/bin/env bash
# Do a run's unconverged steps bias its result? A finished sweep point whose
# solves often ended at solver.max_iterations (frac_steps_unconverged) is run
# on from its final state with a higher cap, and its shear rate compared strain
# by strain with the point's own steady part; and a few of its steps, dumped
# from that state, are solved again under several caps (and plain Gauss-Seidel)
# to see how many passes they need. Written for the decisive study's mu0 0.4,
# tau 1e5 point (docs/paper-reproduction.md "The decisive study"), where 0.29
# of the steps ended at the cap of 1000.
#
#   bash bench/unconverged_bias.sh --point DIR [--cap N] [--strain S] [--label L]
#                                  [--binary PATH] [--report-only]
#
#   --point     a finished point folder (config.toml, checkpoint.bin, timeseries.csv,
#               summary.json): out/paper/decisive-le/points/018-seed=1_mu0=0.4_lambda=316
#   --cap       solver.max_iterations of the continuation (default 10000)
#   --strain    its strain (default 3; the first 1 is its transient in summary.json,
#               but every strain is compared: it starts from a steady state)
#   --binary    the dilatant that runs the continuation (default build/dilatant; the
#               point's own binary compares like with like)
#   --report-only  only write the comparison from the files there
#
# Writes bench/results/unconverged-bias-LABEL/: continuation/ (the run's summary.json,
# timeseries.csv, config.toml), solves.csv (per cap: steps, converged, mean
# passes), comparison.md (printed too), run-info.txt. The continuation resumes
# from its checkpoint when run again. Cost: the continuation about 20-30 min of
# a core per strain at the decisive point; the dumps and solves about 3 min.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

point="" cap=10000 strain=3 label=$(date +%Y%m%d) binary=build/dilatant report_only=0
usage() {
  echo "usage: unconverged_bias.sh --point DIR [--cap N] [--strain S] [--label L]" \
    "[--binary PATH] [--report-only]" >&2
  exit 2
}
while (($# > 0)); do
  case "$1" in
    --point) point=$2; shift 2 ;;
    --cap) cap=$2; shift 2 ;;
    --strain) strain=$2; shift 2 ;;
    --label) label=$2; shift 2 ;;
    --binary) binary=$2; shift 2 ;;
    --report-only) report_only=1; shift ;;
    *) usage ;;
  esac
done
[[ -n $point ]] || usage
for f in config.toml checkpoint.bin timeseries.csv summary.json; do
  [[ -f $point/$f ]] || { echo "unconverged_bias.sh: $point/$f: missing (a finished point?)" >&2; exit 2; }
done
out=bench/results/unconverged-bias-$label
scratch=${TMPDIR:-/tmp}/unconverged-bias-$label
mkdir -p "$out" "$scratch"

if ((!report_only)); then
  sets=(--set "solver.max_iterations=$cap" --set "run.strain=$strain" --set run.transient_strain=1.0)
  run=$out/continuation
  if [[ -f $run/checkpoint.bin && ! -f $run/summary.json ]]; then
    start=(--resume)
  else
    start=(--start-from "$point/checkpoint.bin")
  fi
  if [[ ! -f $run/summary.json ]]; then
    {
      echo "point: $point"
      echo "continuation: $binary run $point/config.toml ${start[*]} ${sets[*]} --out $run"
      echo "binary: $("$binary" --version 2>/dev/null || echo "$binary"), commit $(git rev-parse --short HEAD)"
    } >"$out/run-info.txt"
    "$binary" run "$point/config.toml" "${start[@]}" "${sets[@]}" --out "$run" -q
  fi  # else: run-info.txt says how the continuation there was made
  rm -f "$run/checkpoint.bin" "$run/contacts.csv"  # large; the comparison needs neither

  # Steps dumped from the point's final state under its own settings: the
  # unconverged ones first, a few regular ones besides.
  bash scripts/build.sh release dilatant dilatant-solve-step >/dev/null
  rm -rf "$scratch/steps" "$scratch/dump-run"
  build/dilatant run "$point/config.toml" --start-from "$point/checkpoint.bin" --out "$scratch/dump-run" \
    --dump-steps "$scratch/steps" --dump-unconverged 12 --dump-every 40 --dump-max 6 \
    --set run.strain=0.03 --set run.transient_strain=0.01 -q || true
  echo "label,max_iterations,relaxation,steps,converged,mean_passes" >"$out/solves.csv"
  solve() {  # label cap relaxation
    build/bench/dilatant-solve-step "$scratch/steps" --set "solver.max_iterations=$2" \
      --set "solver.relaxation=$3" --targets 1e-2 |
      awk -v l="$1" -v c="$2" -v r="$3" 'NR > 1 { n++; ok += ($6 == "true"); p += $2 }
        END { printf "%s,%s,%s,%d,%d,%.0f\n", l, c, r, n, ok, p / n }' >>"$out/solves.csv"
  }
  relaxation=$(sed -n 's/^relaxation = //p' "$point/config.toml")
  for c in 1000 2000 5000 20000; do solve "sor" "$c" "$relaxation"; done
  solve "plain-gs" 20000 1.0
  echo "dumps: build/dilatant run ... --dump-steps (commit $(git rev-parse --short HEAD))" >>"$out/run-info.txt"
fi

/usr/bin/python3 - "$point" "$out" >"$out/comparison.md" <<'EOF'
import csv, json, statistics, sys
from pathlib import Path
point, out = Path(sys.argv[1]), Path(sys.argv[2])

def per_strain(rows):
    """Mean gamma_dot (code units) and steps, unconverged share, mean passes per whole strain."""
    blocks = {}
    for r in rows:
        k = int(float(r["strain"]) - 0.01)  # a row ends its interval, a step past it at most
        blocks.setdefault(k, []).append(r)
    out = []
    for k, b in sorted(blocks.items()):
        steps = sum(float(r["steps"]) for r in b)
        out.append((k, statistics.mean(float(r["gamma_dot"]) for r in b), len(b),
                    sum(float(r["unconverged_steps"]) for r in b) / steps,
                    sum(float(r["iterations"]) * float(r["steps"]) for r in b) / steps))
    return out

ran = json.load(open(point / "summary.json"))
transient = next(float(line.split("=")[1]) for line in open(point / "config.toml")
                 if line.startswith("transient_strain"))
own = [r for r in csv.DictReader(open(point / "timeseries.csv"))]
cont = list(csv.DictReader(open(out / "continuation" / "timeseries.csv")))
print(f"# Unconverged steps and the shear rate: {point.name}\n")
print(f"The point: {ran['steps']} steps, {ran['frac_steps_unconverged']:.3f} of them at the cap, "
      f"{ran['mean_iterations']:.0f} passes a step on average; gamma_dot {ran['gamma_dot']:.4g} "
      f"+- {ran['gamma_dot_err']:.2g} (paper units, averaged after strain {transient:g}).\n")
print("Per strain, gamma_dot in code units (the time series'; mean of its rows):\n")
print("| run | strain | gamma_dot | rows | unconverged share | passes a step |")
print("|---|---|---|---|---|---|")
for name, rows in (("the point (cap of its config)", own), ("continuation (higher cap)", cont)):
    for k, g, n, u, it in per_strain(rows):
        print(f"| {name} | {k}-{k + 1} | {g:.3g} | {n} | {u:.3f} | {it:.0f} |")
steady = [float(r["gamma_dot"]) for r in own if float(r["strain"]) > transient]
cont_g = [float(r["gamma_dot"]) for r in cont]
def block_error(v, size=10):
    blocks = [statistics.mean(v[i:i + size]) for i in range(0, len(v) - size + 1, size)]
    return statistics.stdev(blocks) / len(blocks) ** 0.5 if len(blocks) > 1 else float("nan")
a, b = statistics.mean(steady), statistics.mean(cont_g)
ea, eb = block_error(steady), block_error(cont_g)
print(f"\nRow means: the point after strain {transient:g} {a:.4g} +- {ea:.2g} ({len(steady)} rows), the "
      f"continuation {b:.4g} +- {eb:.2g} ({len(cont_g)} rows); ratio {b / a:.3f}, "
      f"{(b - a) / (ea ** 2 + eb ** 2) ** 0.5:.1f} combined errors (blocks of 10 rows, 0.5 strain).\n")
print("Dumped steps solved again (solves.csv):\n")
print("| solver | max_iterations | steps | converged | mean passes |")
print("|---|---|---|---|---|")
for r in csv.DictReader(open(out / "solves.csv")):
    print(f"| {r['label']} (relaxation {r['relaxation']}) | {r['max_iterations']} | {r['steps']} | "
          f"{r['converged']} | {r['mean_passes']} |")
EOF
cat "$out/comparison.md"
