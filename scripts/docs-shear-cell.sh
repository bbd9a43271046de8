#!/usr/bin/env bash
# Regenerates the figures and tables of docs/shear-cell.md from committed configs:
#  1. two points of the paper's Fig. 1 (examples/cell/viscous.toml, thickened.toml);
#  2. the wall-grip check: thickened.toml at mu0 = 0.2, 0.3, 0.4 (5 strain units).
# About 30 minutes on the 2-core machine. Outputs: out/docs/, docs/shear-cell/.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
bash scripts/install-deps.sh python3-matplotlib
bash scripts/build.sh release
run() { ./build/dilatant run --quiet "$@"; }
run examples/cell/viscous.toml --out out/docs/viscous &
run examples/cell/thickened.toml --out out/docs/thickened
for mu in 0.2 0.3 0.4; do
  run examples/cell/thickened.toml --set friction.mu0=$mu --set run.strain=5.0 \
    --set run.transient_strain=2.0 --out out/docs/mu$mu
done
wait
# The small result files of every run are committed next to the figures.
for run in viscous thickened mu0.2 mu0.3 mu0.4; do
  mkdir -p docs/shear-cell/data/$run
  cp out/docs/$run/{summary.json,config.toml,timeseries.csv,velocity_profile.csv,sommerfeld_hist.csv} \
    docs/shear-cell/data/$run/
done
PYTHONPATH=python /usr/bin/python3 -m dilatant.plots.shear_cell docs/shear-cell/fig1 \
  "lambda 1=out/docs/viscous" "lambda 100=out/docs/thickened"
PYTHONPATH=python /usr/bin/python3 -m dilatant.plots.shear_cell docs/shear-cell/walls \
  "mu0 0.1=out/docs/thickened" "mu0 0.2=out/docs/mu0.2" "mu0 0.3=out/docs/mu0.3" \
  "mu0 0.4=out/docs/mu0.4"
