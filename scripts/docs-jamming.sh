#!/usr/bin/env bash
# The jamming fractions of docs/jamming.md: `dilatant jam` with
# examples/jamming/sediment.toml at every mu0 of the list, the shear-jamming
# sweep examples/jamming/shear-jamming.toml, then the tables and the figure
# (dilatant.plots.jamming), the tables into data/jamming/ (dilatant
# predict's, with the bulk flow states of the Lees–Edwards ramps) and the
# phase diagram of `dilatant predict --grid`. Resumable: a
# mu0 whose summary.json exists is not run again, the sweep resumes.
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
# Shear jamming in the cell (phi_c(mu0)); DILATANT_JAM_SHEAR=0 skips it.
if [[ ${DILATANT_JAM_SHEAR:-1} != 0 ]]; then
  "$bin" sweep examples/jamming/shear-jamming.toml --out "$out/shear"
  "$bin" sweep examples/jamming/shear-jamming-refine.toml --out "$out/shear-refine"
fi
mkdir -p "$docs"
PYTHONPATH=python /usr/bin/python3 -m dilatant.plots.jamming "$out" "$docs"
if [[ -f $out/shear/flowcurves.csv ]]; then cp "$out/shear/flowcurves.csv" "$docs/shear-flowcurves.csv"; fi
if [[ -f $out/shear-refine/flowcurves.csv ]]; then
  cp "$out/shear-refine/flowcurves.csv" "$docs/shear-refine-flowcurves.csv"
fi
# The tables dilatant predict compiles in: phi_max_BL(mu0), and the
# frictional onsets (`dilatant analyze`'s contact onsets, docs/analysis.md
# rule 8) of the decisive study's Lees-Edwards flow curves (docs/jamming.md
# "The onset scale"; decisive-le-mu0.4 is decisive-le's mu0 0.4 run again
# with its steps converged, so it replaces that curve).
cp "$docs/phi_max_bl.csv" data/jamming/phi_max_bl.csv
onset_pairs=()
for sweep in decisive-le decisive-le-mu0.4 decisive-le-mu0.2 decisive-le-mu0 decisive-le-mu0-far; do
  "$bin" analyze "docs/paper-reproduction/$sweep/flowcurves.csv" --out "$out/onsets/$sweep" --no-plots -q
  [[ $sweep == decisive-le-mu0.4 ]] && onset_pairs+=(--rerun)
  onset_pairs+=("docs/paper-reproduction/$sweep/flowcurves.csv" "$out/onsets/$sweep/curves.csv")
done
PYTHONPATH=python /usr/bin/python3 -m dilatant.plots.onset_table --header literal "${onset_pairs[@]}" \
  > data/jamming/onsets.csv.part && mv data/jamming/onsets.csv.part data/jamming/onsets.csv
# The flow states measured in bulk (Lees–Edwards ramps), which dilatant
# predict asks before the sediment table (docs/jamming.md "The predictor's
# sources"; data/jamming/README.md): read from the committed flow curves.
mkdir -p "$out"
PYTHONPATH=python /usr/bin/python3 -m dilatant.plots.bulk_flow_states docs/paper-reproduction \
  > data/jamming/bulk_flow_states.csv.part 2> "$out/bulk_flow_states.log"
mv data/jamming/bulk_flow_states.csv.part data/jamming/bulk_flow_states.csv
# The predictor against every flow curve of docs/paper-reproduction.
PYTHONPATH=python /usr/bin/python3 -m dilatant.plots.predictor_checks "$bin" "$docs/predictor_checks.csv" \
  docs/paper-reproduction
# The phase diagram of dilatant predict --grid (from the table as built).
"$bin" predict --grid --out "$out/phase-diagram"
cp "$out/phase-diagram/phase_diagram.png" "$docs/"
