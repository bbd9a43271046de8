#!/usr/bin/env bash
# Whole-run benchmark (issue 4): shears the paper's cell for a fixed strain at
# each point of bench/configs/ on 1 and 2 threads and keeps each summary.json
# (cost by stage, ns per contact update, steps and sweeps, eta with its error)
# under bench/results/LABEL/. bench/report.py turns them into the tables of
# bench/RESULTS.md.
#
#   bash bench/whole_run.sh [--label L] [--binary PATH] [--strain S] [--threads "1 2"]
#                           [--points "thickened viscous coulomb"] [-- extra --set args]
#
# --binary runs another build (e.g. an older commit, for before/after tables);
# --threads none runs a build that predates solver.threads. Run it on a quiet
# machine: the wall times are the result.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

label="$(git rev-parse --short HEAD)"
binary=""
strain=1.0
threads="1 2"
points="thickened viscous coulomb"
extra=()
while (($#)); do
  case "$1" in
    --label) label=$2; shift 2 ;;
    --binary) binary=$2; shift 2 ;;
    --strain) strain=$2; shift 2 ;;
    --threads) threads=$2; shift 2 ;;
    --points) points=$2; shift 2 ;;
    --) shift; extra=("$@"); break ;;
    *) echo "whole_run.sh: unknown argument $1" >&2; exit 2 ;;
  esac
done
if [[ -z "$binary" ]]; then
  bash scripts/install-deps.sh
  bash scripts/build.sh release dilatant
  binary=build/dilatant
fi

results="bench/results/$label"
mkdir -p "$results"
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
for point in $points; do
  for t in $threads; do
    thread_args=()
    [[ "$t" == none ]] || thread_args=(--set "solver.threads=$t")
    echo "=== $label $point threads=$t strain=$strain ($(uptime | sed 's/.*load average: /load /'))"
    "$binary" run "bench/configs/$point.toml" --out "$scratch/$point-t$t" --quiet \
      --set "run.strain=$strain" "${thread_args[@]}" "${extra[@]}"
    cp "$scratch/$point-t$t/summary.json" "$results/$point-t$t.json"
    cp "$scratch/$point-t$t/config.toml" "$results/$point-t$t.toml"
  done
done
{
  echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs)"
  echo "compiler: $(c++ --version | head -1)"
  echo "commit: $(git rev-parse --short HEAD) (binary: $binary)"
  echo "date: $(date -u +%Y-%m-%dT%H:%MZ)"
} > "$results/machine.txt"
/usr/bin/env python3 bench/report.py "$results"
