#!/usr/bin/env bash
# Regenerates the figures and table of docs/shear-cell.md: runs the two committed
# configs (examples/cell/viscous.toml, thickened.toml) at the paper's cell size,
# in parallel (about 10-20 minutes each on one core of the 2-core machine), then
# draws the figures into docs/shear-cell/.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
bash scripts/install-deps.sh python3-matplotlib
bash scripts/build.sh release
./build/dilatant run examples/cell/viscous.toml --out out/docs/viscous --quiet &
./build/dilatant run examples/cell/thickened.toml --out out/docs/thickened --quiet &
wait
/usr/bin/python3 scripts/shear_cell_figures.py docs/shear-cell \
  "lambda 1=out/docs/viscous" "lambda 100=out/docs/thickened"
git rev-parse --short HEAD > docs/shear-cell/commit.txt 2>/dev/null || true
