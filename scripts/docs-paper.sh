#!/usr/bin/env bash
# Runs the sweeps of the paper's figures (examples/paper/: Fig. 2, whose mu0 0.1
# curve gives Fig. 1b-d, the coulomb control, the denser boundary cells, the DST
# checks) at the paper's cell size, and those of the Newtonian branch (the
# literal model's dense window, fluid forces, eta_N(phi); a 15 x 10 x 18 cell),
# and those of the three regimes (the DST map's ramps to the jam, the onset's
# s_c scaling),
# copies their tables and figures into docs/paper-reproduction/<sweep>/
# and writes docs/paper-reproduction/tables.md, control.png (Stribeck against
# the coulomb control), newtonian.png, lees-edwards/comparison.png (walls
# against Lees–Edwards) and decisive-fig2.png (the decisive study's mu0 in one
# figure) for docs/paper-reproduction.md.
# Hours on the 2-core machine (docs/sweeps.md "The paper's figures"); resumable:
# run it again after an interruption and finished points are skipped.
#   scripts/docs-paper.sh [dilatant sweep options...]   e.g. --jobs 2
# Environment: DILATANT_PAPER_OUT (default out/paper), DILATANT_PAPER_DOCS
# (default docs/paper-reproduction), DILATANT_PAPER_SWEEPS (default
# "fig2 coulomb boundary dst-checks dense-window newtonian-fluid newtonian-phi
# dense-window-phi dst-map dst-map-mu0 dst-map-phi dst-map-dense dst-map-seeds
# dst-size dst-size-phi dst-map-films sc-scaling lees-edwards-fig2 lees-edwards-dst decisive-le decisive-le-mu0.4 decisive-le-mu0.4-refine decisive-le-refine decisive-le-mu0 decisive-le-mu0-refine decisive-le-mu0.2
# decisive-le-mu0.2-refine decisive-le-mu0-far decisive-walls-phi0.62 decisive-walls decisive-walls-refine
# bulk-boundary"),
# DILATANT_SKIP_BUILD=1 to use build/ as it is, DILATANT=PATH to run another
# binary (a study pinned to the version it started with: scripts/pinned-binary.sh;
# its table is analysed by build/dilatant all the same, into OUT/SWEEP/analysis-current),
# DILATANT_REFINE=PATH the binary of the *-refine sweeps (default build/dilatant).
# DILATANT_PAPER_NO_RUN=1 runs no sweep: it copies and analyses the tables the
# sweeps have now (a study still running writes each point's row as it ends,
# the others `pending`) and redraws from them, in seconds.
# A sweep with a folder in runs/ (a study kept in the repository across
# machines, scripts/study-archive.sh) is restored from it before it runs and
# saved to it after.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
out=${DILATANT_PAPER_OUT:-out/paper}
docs=${DILATANT_PAPER_DOCS:-docs/paper-reproduction}
if [[ -z ${DILATANT_SKIP_BUILD:-} ]]; then
  bash scripts/install-deps.sh python3-matplotlib
  bash scripts/build.sh release dilatant
fi
status=0
sweeps="fig2 coulomb boundary dst-checks dense-window newtonian-fluid newtonian-phi dense-window-phi
dst-map dst-map-mu0 dst-map-phi dst-map-dense dst-map-seeds dst-size dst-size-phi dst-map-films sc-scaling
lees-edwards-fig2 lees-edwards-dst decisive-le decisive-le-mu0.4 decisive-le-mu0.4-refine decisive-le-refine decisive-le-mu0
decisive-le-mu0-refine decisive-le-mu0.2 decisive-le-mu0.2-refine decisive-le-mu0-far decisive-walls-phi0.62
decisive-walls decisive-walls-refine bulk-boundary"
for sweep in ${DILATANT_PAPER_SWEEPS:-$sweeps}; do
  binary=${DILATANT:-./build/dilatant}
  # A refinement (NAME-refine.toml, sweep.refines) refines NAME's ramps in $out,
  # with DILATANT_REFINE (default build/dilatant: sweep.refines came in 0.10,
  # after the binary a study may be pinned to).
  refines=()
  if [[ $sweep == *-refine ]]; then
    binary=${DILATANT_REFINE:-./build/dilatant}
    refines=(--set "sweep.refines=\"$(realpath -m "$out/${sweep%-refine}")\"")
  fi
  if [[ -n ${DILATANT_PAPER_NO_RUN:-} ]]; then
    binary=none  # the table as it stands, analysed by this version (below)
  else
    if [[ -d runs/$sweep ]]; then DILATANT_PAPER_OUT=$out bash scripts/study-archive.sh restore "$sweep"; fi
    # A failed point does not stop the others (exit 1): copy what there is, go on.
    "$binary" sweep "examples/paper/$sweep.toml" --out "$out/$sweep" "${refines[@]}" "$@" ||
      status=$?
    if [[ -d runs/$sweep ]]; then DILATANT_PAPER_OUT=$out bash scripts/study-archive.sh save "$sweep"; fi
  fi
  if [[ ! -f $out/$sweep/flowcurves.csv ]]; then continue; fi  # refused before it ran
  mkdir -p "$docs/$sweep"
  cp "$out/$sweep/flowcurves.csv" "$out/$sweep/sweep.toml" "$docs/$sweep/"
  if [[ $binary != ./build/dilatant && -f $docs/$sweep/flowcurves.csv ]]; then
    # A sweep run by a pinned binary (DILATANT), or not run here
    # (DILATANT_PAPER_NO_RUN), is analysed by this version: the analysis reads
    # the table alone, and its rules (fall_stress since 0.12.0) are this version's.
    ./build/dilatant analyze "$docs/$sweep/flowcurves.csv" --out "$out/$sweep/analysis-current" \
      --no-plots >/dev/null || status=$?
    cp "$out/$sweep/analysis-current/curves.csv" "$docs/$sweep/"
  elif [[ -d $out/$sweep/analysis ]]; then cp "$out/$sweep/analysis/curves.csv" "$docs/$sweep/"; fi
  # The jams' cold starts (sweep.confirm_jams): their summaries, one per jammed point.
  for cold in "$out/$sweep"/points/*/cold-start/summary.json; do
    [[ -f $cold ]] || continue
    mkdir -p "$docs/$sweep/cold-starts"
    point=$(basename "$(dirname "$(dirname "$cold")")")
    cp "$cold" "$docs/$sweep/cold-starts/$point.json"
  done
  # Fig. 1b-d come from fig2's mu0 0.1 curve, and from the decisive study's
  # (the paper's cell at its Newtonian branch); the other sweeps need their
  # flow curves only.
  plots=(flow_curves)
  if [[ $sweep == fig2 || $sweep == decisive-* ]]; then
    plots+=(fig1b_viscosity fig1c_sommerfeld fig1d_contacts)
  fi
  if [[ $sweep == decisive-* ]]; then
    # The sticking contacts point by point (why the Newtonian branch follows mu0).
    PYTHONPATH=python /usr/bin/python3 -m dilatant.plots.contact_states "$out/$sweep" \
      > "$docs/$sweep/contact_states.csv.part"
    mv "$docs/$sweep/contact_states.csv.part" "$docs/$sweep/contact_states.csv"
    # The points' table of docs/paper-reproduction.md "The decisive study".
    PYTHONPATH=python /usr/bin/python3 -m dilatant.plots.ramp_table "$docs/$sweep" \
      > "$docs/$sweep/points_table.md.part"
    mv "$docs/$sweep/points_table.md.part" "$docs/$sweep/points_table.md"
  fi
  for plot in "${plots[@]}"; do
    if [[ -f $out/$sweep/plots/$plot.png ]]; then cp "$out/$sweep/plots/$plot".{png,svg} "$docs/$sweep/"; fi
  done
done
if [[ -f $docs/decisive-le/flowcurves.csv ]]; then
  # The decisive study's Fig. 2: every mu0 of its sweeps in one figure.
  PYTHONPATH=python /usr/bin/python3 -m dilatant.plots.decisive_fig2 "$docs" \
    decisive-le decisive-le-mu0.4 decisive-le-mu0 decisive-le-mu0.2 decisive-le-mu0-far
  # With walls and without: the wall cell's ramps beside the box's of the same mu0.
  PYTHONPATH=python /usr/bin/python3 -m dilatant.plots.decisive_fig2 "$docs" \
    decisive-le decisive-le-mu0.4 decisive-walls --name decisive-walls-fig2
fi
# Smooth flow or stop-and-go, point by point (docs/paper-reproduction.md "Stop
# and go on the middle branch"): the time series of every point the study's
# sweeps have, and four of seed 1's mu0 0.4 points across the fall drawn.
intermittent=()
for sweep in decisive-le-mu0.4 decisive-le-mu0.4-refine decisive-le-mu0 decisive-le-mu0-refine \
  decisive-le-mu0.2 decisive-le-mu0.2-refine decisive-le-mu0-far decisive-walls decisive-walls-refine; do
  # the sweep's folder if it ran here, else its archive (runs/, gzipped series)
  if [[ -d $out/$sweep/points ]]; then
    intermittent+=("$out/$sweep")
  elif [[ -d runs/$sweep/points ]]; then intermittent+=("runs/$sweep"); fi
done
fall=(runs/decisive-le-mu0.4-refine/points/003-seed=1_lambda=68.13
  runs/decisive-le-mu0.4/points/006-seed=1_lambda=100
  runs/decisive-le-mu0.4-refine/points/004-seed=1_lambda=146.8
  runs/decisive-le-mu0.4/points/007-seed=1_lambda=316)
if ((${#intermittent[@]})) && [[ -f ${fall[2]}/summary.json ]]; then
  PYTHONPATH=python /usr/bin/python3 -m dilatant.plots.rate_intermittency \
    "$docs/rate-intermittency" "${intermittent[@]}" --figure "${fall[@]}" || status=$?
fi
# The decisive study's curves point by point (dilatant.plots.curve_pairs): do
# two seeds agree within their error bars, does the mu0 0.4 rerun repeat the
# first run (docs/paper-reproduction.md "Seeds and reruns, point by point").
pairs() { PYTHONPATH=python /usr/bin/python3 -m dilatant.plots.curve_pairs "$@"; }
if [[ -f $docs/decisive-le/flowcurves.csv ]]; then
  pairs "$docs/decisive-le/flowcurves.csv" "$docs/decisive-le/flowcurves.csv" --a-where mu0=0.1 \
    --a-where cell.seed=1 --b-where mu0=0.1 --b-where cell.seed=2 \
    --out "$docs/decisive-le/pairs-seeds-mu0.1" || status=$?
fi
if [[ -f $docs/decisive-le/flowcurves.csv && -f $docs/decisive-le-mu0.4/flowcurves.csv ]]; then
  pairs "$docs/decisive-le-mu0.4/flowcurves.csv" "$docs/decisive-le-mu0.4/flowcurves.csv" \
    --a-where cell.seed=1 --b-where cell.seed=2 --out "$docs/decisive-le-mu0.4/pairs-seeds" ||
    status=$?
  pairs "$docs/decisive-le/flowcurves.csv" "$docs/decisive-le-mu0.4/flowcurves.csv" --a-where mu0=0.4 \
    --a-where cell.seed=1 --b-where cell.seed=1 --out "$docs/decisive-le-mu0.4/pairs-rerun-seed1" ||
    status=$?
  # The same below tau 1e5, where at most 0.023 of the first run's steps hit
  # its cap of 1000 (at tau 1e5, 0.29 did).
  pairs "$docs/decisive-le/flowcurves.csv" "$docs/decisive-le-mu0.4/flowcurves.csv" --a-where mu0=0.4 \
    --a-where cell.seed=1 --b-where cell.seed=1 --b-where 'lambda<316' \
    --out "$docs/decisive-le-mu0.4/pairs-rerun-seed1-below-1e5" || status=$?
fi
if [[ -f $docs/fig2/flowcurves.csv && -f $docs/coulomb/flowcurves.csv ]]; then
  PYTHONPATH=python /usr/bin/python3 -m dilatant.plots.coulomb_control "$docs"
fi
if [[ -f $docs/newtonian-fluid/flowcurves.csv ]]; then
  PYTHONPATH=python /usr/bin/python3 -m dilatant.plots.newtonian "$docs"
fi
if [[ -f $docs/dst-map/flowcurves.csv ]]; then
  # The map reads the tables of docs/jamming/ (scripts/docs-jamming.sh).
  maps=("$docs/dst-map")
  # The literal model's ramps in the map's cell, and in the paper's cell
  # (dst-map-films's model differs: its table is read in the text).
  for more in dst-map-mu0 dst-map-phi dst-map-dense dst-map-seeds; do
    if [[ -f $docs/$more/flowcurves.csv ]]; then maps+=("$docs/$more"); fi
  done
  for more in dst-size dst-size-phi; do  # the paper's cell: open markers
    if [[ -f $docs/$more/flowcurves.csv ]]; then maps+=("$docs/$more=25x10x27"); fi
  done
  PYTHONPATH=python /usr/bin/python3 -m dilatant.plots.dst_map "$docs/dst-map" dst_map "${maps[@]}"
fi
if [[ -f $docs/lees-edwards-fig2/flowcurves.csv || -f $docs/lees-edwards-dst/flowcurves.csv ]]; then
  # Walls against Lees–Edwards (issue 16): table and figure in $docs/lees-edwards/.
  PYTHONPATH=python /usr/bin/python3 -m dilatant.plots.lees_edwards "$docs"
fi
if [[ -z ${DILATANT_PAPER_NO_RUN:-} && " ${DILATANT_PAPER_SWEEPS:-$sweeps} " == *" sc-scaling "* && -f $docs/sc-scaling/flowcurves.csv ]]; then
  # The s_c scaling's two ramps from saved states (docs/paper-reproduction.md
  # "The onset's s_c scaling"): s_c 5e-6 carried on from its lambda 100 state,
  # s_c 5e-4 started from the s_c 5e-5 flowing state at lambda 0.1.
  ramp=examples/paper/sc-scaling-ramp.toml
  for start in "$out"/sc-scaling/points/*-s_c=5e-06_lambda=100/checkpoint.bin; do
    [[ -f $start ]] || continue
    DILATANT=build/dilatant bash scripts/ramp_from_state.sh "$ramp" "$start" "$out/sc-scaling-5e-6" \
      --set friction.s_c=5e-6 300.0 1000.0 3000.0 || status=$?
    mkdir -p "$docs/sc-scaling-5e-6"
    for point in "$out"/sc-scaling-5e-6/lambda=*; do
      if [[ -f $point/summary.json ]]; then
        cp "$point/summary.json" "$docs/sc-scaling-5e-6/summary-$(basename "$point" | tr = -).json"
      fi
    done
  done
  for start in "$out"/sc-scaling/points/*-s_c=5e-05_lambda=0.1/checkpoint.bin; do
    [[ -f $start ]] || continue
    DILATANT=build/dilatant bash scripts/ramp_from_state.sh "$ramp" "$start" "$out/sc-scaling-ramp" \
      0.1 || status=$?
    mkdir -p "$docs/sc-scaling-ramp"
    cp "$out/sc-scaling-ramp/lambda=0.1"/{summary.json,timeseries.csv} "$docs/sc-scaling-ramp/" || status=$?
  done
  PYTHONPATH=python /usr/bin/python3 -m dilatant.plots.sc_scaling "$docs"
fi
PYTHONPATH=python /usr/bin/python3 -m dilatant.plots.paper_tables "$docs" >"$docs/tables.md.part"
mv "$docs/tables.md.part" "$docs/tables.md"
exit "$status"
