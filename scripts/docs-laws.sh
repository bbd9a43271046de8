#!/usr/bin/env bash
# The study of docs/laws.md (issue 33): the critical-load model's flow curves
# (examples/laws/critical-load-{viscous,inertial}.toml, sweeps of phi and
# lambda in the Lees-Edwards box with films and drag), their Wyart-Cates fit
# (`dilatant analyze --model wyart-cates`), and the tables and figures copied
# into docs/laws/<study>/. Resumable: the sweeps skip finished points.
#   bash scripts/docs-laws.sh
# Environment: DILATANT_LAWS_OUT (default out/laws), DILATANT_LAWS_DOCS
# (default docs/laws), DILATANT_LAWS_JOBS (points side by side; default 0, one
# per core), DILATANT_SKIP_BUILD=1 to use build/ as it is.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
out=${DILATANT_LAWS_OUT:-out/laws}
docs=${DILATANT_LAWS_DOCS:-docs/laws}
bin=${DILATANT_BIN:-./build/dilatant}
if [[ -z ${DILATANT_SKIP_BUILD:-} ]]; then
  bash scripts/install-deps.sh python3-matplotlib
  bash scripts/build.sh release dilatant
fi
# Two studies: the onset where the flow is viscous (the Wyart-Cates model's
# regime), where it is inertial, and the viscous one as stress ramps (the
# contrasts).
for study in viscous viscous-mu1 inertial stress-ramp; do
  "$bin" sweep "examples/laws/critical-load-$study.toml" --out "$out/$study" \
    --set "sweep.jobs=${DILATANT_LAWS_JOBS:-0}"
  # A fit that finds nothing to fit exits 2; the tables of the analysis stay.
  "$bin" analyze "$out/$study/flowcurves.csv" --model wyart-cates --out "$out/$study-fit" ||
    echo "docs-laws.sh: no Wyart-Cates fit of $study (see above)"
  mkdir -p "$docs/$study"
  cp "$out/$study/flowcurves.csv" "$docs/$study/flowcurves.csv"
  for f in wyart_cates.json wyart_cates_curves.csv wyart_cates_map.csv wyart_cates.png \
    curves.csv flow_curves.png; do
    if [[ -f $out/$study-fit/$f ]]; then cp "$out/$study-fit/$f" "$docs/$study/$f"; fi
  done
done
# The viscous studies fitted in the nominal phi too (--wc-phi nominal): how far
# the fit moves with the fraction it is made in (docs/laws.md "Which phi"); and
# weighted by each point's eta_err (--wc-weights errors): why these
# rate-controlled fits are not (docs/laws.md "How well it fits").
for study in viscous viscous-mu1; do
  "$bin" analyze "$out/$study/flowcurves.csv" --model wyart-cates --wc-phi nominal \
    --out "$out/$study-fit-nominal" -q --no-plots
  cp "$out/$study-fit-nominal/wyart_cates.json" "$docs/$study/wyart_cates_nominal.json"
  "$bin" analyze "$out/$study/flowcurves.csv" --model wyart-cates --wc-weights errors \
    --out "$out/$study-fit-errors" -q --no-plots
  cp "$out/$study-fit-errors/wyart_cates.json" "$docs/$study/wyart_cates_errors.json"
done
# The stress ramps' first points at phi 0.55-0.57, read as jams (docs/laws.md
# "A finding"): their time series.
for point in "$out"/stress-ramp/points/*lambda=0.1; do
  cp "$point/timeseries.csv" "$docs/stress-ramp/timeseries-$(basename "$point").csv"
done
"$bin" --version >"$docs/version.txt"
