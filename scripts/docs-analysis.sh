#!/usr/bin/env bash
# Regenerates docs/analysis/ (the figures and tables of docs/analysis.md):
#  1. the synthetic example examples/analysis/ from its generator (fixed seed, so
#     the committed files come back unchanged);
#  2. `dilatant analyze` on its manifest, and on the small simulated sweep
#     tests/analysis/data/flowcurves.csv;
#  3. the recovered-vs-true table of the example.
# Under a minute. Outputs: out/docs/analysis/, docs/analysis/.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
bash scripts/install-deps.sh python3-matplotlib
bash scripts/build.sh release dilatant
/usr/bin/python3 examples/analysis/make_example.py
./build/dilatant analyze examples/analysis/manifest.toml --out out/docs/analysis/example
./build/dilatant analyze tests/analysis/data/flowcurves.csv --out out/docs/analysis/sweep
for run in example sweep; do
  mkdir -p docs/analysis/$run
  cp out/docs/analysis/$run/{curves.csv,fits.json} out/docs/analysis/$run/*.{png,svg} \
    docs/analysis/$run/
done
PYTHONPATH=python /usr/bin/python3 -m dilatant.plots.analysis_truth_table out/docs/analysis/example \
  examples/analysis/truth.json >docs/analysis/example/table.md
