#!/usr/bin/env bash
# The table phi_max_BL(mu0) of docs/jamming.md: `dilatant jam` with
# examples/jamming/sediment.toml at every mu0 of the list, then the table and
# the figure (scripts/jamming_figures.py). Resumable: a mu0 whose summary.json
# exists is not run again.
#   scripts/docs-jamming.sh
# Environment: DILATANT_JAM_OUT (default out/jamming), DILATANT_JAM_DOCS
# (default docs/jamming), DILATANT_JAM_MU0 (default "0 0.1 0.4 1 0.2 0.3 0.6 0.05",
# the most telling first), DILATANT_SKIP_BUILD=1 to use build/ as it is.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
out=${DILATANT_JAM_OUT:-out/jamming}
docs=${DILATANT_JAM_DOCS:-docs/jamming}
bin=${DILATANT_BIN:-./build/dilatant}
if [[ -z ${DILATANT_SKIP_BUILD:-} ]]; then
  bash scripts/install-deps.sh python3-matplotlib
  bash scripts/build.sh release dilatant
fi
for mu0 in ${DILATANT_JAM_MU0:-0 0.1 0.4 1 0.2 0.3 0.6 0.05}; do
  dir=$out/mu0-$mu0
  if [[ -f $dir/summary.json ]]; then continue; fi
  "$bin" jam examples/jamming/sediment.toml --set "friction.mu0=$mu0" --out "$dir"
done
mkdir -p "$docs"
/usr/bin/python3 scripts/jamming_figures.py "$out" "$docs"
