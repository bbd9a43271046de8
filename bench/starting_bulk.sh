#!/usr/bin/env bash
# The starting bulk fraction of the paper's wall cell (25 x 10 x 27 R, rough
# walls, seed 1: bench/configs/coulomb.toml's cell; the friction law plays no
# part in a packing) against its nominal phi, and
# the bulk rule's search for a cold start that begins at a given bulk fraction
# (sweep.cold_start_phi = "bulk", docs/sweeps.md "Ramps to the jam"), with
# bench/tools/starting_bulk.cpp. Packings only, nothing sheared: about 2
# minutes of one core.
#
#   bash bench/starting_bulk.sh [--label L] [--binary-dir DIR]
#
# Writes bench/results/starting-bulk-LABEL/{scan,search}.csv and
# bench/results/starting-bulk-LABEL/version.txt.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
label=$(date +%Y%m%d)
tools=build/bench
while (($#)); do
  case $1 in
    --label) label=$2; shift 2 ;;
    --binary-dir) tools=$2; shift 2 ;;
    *) echo "$0: unknown argument '$1'" >&2; exit 2 ;;
  esac
done
if [[ $tools == build/bench ]]; then
  bash scripts/install-deps.sh
  bash scripts/build.sh release dilatant dilatant-starting-bulk
fi
out=bench/results/starting-bulk-$label
mkdir -p "$out"
# The search starts from nominal 0.61, as a cold start of the decisive wall
# study's ramps would (examples/paper/decisive-walls.toml: nominal 0.62).
"$tools/dilatant-starting-bulk" bench/configs/coulomb.toml --set cell.phi=0.61 \
  --scan 0.600,0.620,0.002 --targets 0.595,0.598,0.600,0.603 --out "$out"
# The version of the tree the tool was built from (its dilatant beside it).
"$tools/../dilatant" --version >"$out/version.txt"
