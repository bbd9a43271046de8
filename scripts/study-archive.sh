#!/usr/bin/env bash
# Keeps a long sweep's progress in the repository, so that a study which
# outlasts a session also outlasts the machine it ran on (a new session's
# machine starts bare: out/ is gone, and with it every ramp's states).
#
#   scripts/study-archive.sh save STUDY      out/paper/STUDY -> runs/STUDY
#   scripts/study-archive.sh restore STUDY   runs/STUDY -> out/paper/STUDY
#
# What is kept, per point folder points/NNN-label/ (and its cold-start/):
#   config.toml, summary.json, velocity_profile.csv, sommerfeld_hist.csv: what
#     makes a finished point Done for the sweep (src/sweep/point_folder.hpp)
#     and what the tables and figures read;
#   timeseries.csv.gz: the point's time series (the steadiness test, plots);
#   checkpoint.bin.gz: the state; a continued point starts from the previous
#     point's, an interrupted point resumes from its own, a refinement and a
#     jam's cold start read the ramp's. Kept for every point: a ramp's
#     states are what cannot be had again without rerunning the ramp.
# contacts.csv (the last step's contact list, a few MB) and snapshots are
# left out: no table or figure reads them.
# `restore` writes only files that are missing from out/ (it never overwrites
# a newer local run); `save` rewrites runs/STUDY from out/ (stale files go).
# Both refuse (exit 2) while a sweep runs in out/paper/STUDY.
# Environment: DILATANT_PAPER_OUT (default out/paper), DILATANT_RUNS (default
# runs).
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
usage() {
  echo "usage: scripts/study-archive.sh save|restore STUDY" >&2
  exit 2
}
(($# == 2)) || usage
action=$1
study=$2
out=${DILATANT_PAPER_OUT:-out/paper}/$study
archive=${DILATANT_RUNS:-runs}/$study
plain=(config.toml summary.json velocity_profile.csv sommerfeld_hist.csv)
packed=(timeseries.csv checkpoint.bin)

# Copies one point folder's kept files from $1 to $2 (gzip-packing the large ones).
save_folder() {
  local from=$1 to=$2 f
  mkdir -p "$to"
  for f in "${plain[@]}"; do
    if [[ -f $from/$f ]]; then cp "$from/$f" "$to/$f"; fi
  done
  for f in "${packed[@]}"; do
    if [[ -f $from/$f ]]; then gzip -9 -n -c "$from/$f" >"$to/$f.gz.part" && mv "$to/$f.gz.part" "$to/$f.gz"; fi
  done
}

# The reverse, writing only what $2 lacks; files are written then renamed.
restore_folder() {
  local from=$1 to=$2 f
  mkdir -p "$to"
  for f in "${plain[@]}"; do
    if [[ -f $from/$f && ! -e $to/$f ]]; then cp "$from/$f" "$to/$f.part" && mv "$to/$f.part" "$to/$f"; fi
  done
  for f in "${packed[@]}"; do
    if [[ -f $from/$f.gz && ! -e $to/$f ]]; then
      gzip -d -c "$from/$f.gz" >"$to/$f.part" && mv "$to/$f.part" "$to/$f"
    fi
  done
}

# Applies save_folder or restore_folder ($1) to every point folder of $2 and
# its jam's cold start, writing into the same names under $3.
each_point() {
  local copy=$1 from=$2 to=$3 point name
  for point in "$from"/points/*/; do
    point=${point%/}
    name=$(basename "$point")
    "$copy" "$point" "$to/points/$name"
    if [[ -d $point/cold-start ]]; then "$copy" "$point/cold-start" "$to/points/$name/cold-start"; fi
  done
}

# A sweep running in $out (it holds $out/.dilatant.lock, src/io/folder_lock.hpp)
# writes checkpoints and time series while they are copied: a save could pair
# one point's older checkpoint with its newer time series, a restore could
# write beside a file being renamed. Refused (exit 2) naming the holder.
refuse_if_running() {
  local lock=$out/.dilatant.lock
  [[ -f $lock ]] || return 0
  if ! flock -n "$lock" true; then
    echo "study-archive: $out: in use by $(tr -d '\n' <"$lock" || echo 'another dilatant');" \
      "stop it first (SIGTERM: its running points checkpoint), then $action again" >&2
    exit 2
  fi
}

case $action in
  save)
    [[ -d $out/points ]] || {
      echo "study-archive: $out/points: no such folder (nothing has run)" >&2
      exit 2
    }
    refuse_if_running
    rm -rf "$archive.part"
    mkdir -p "$archive.part/points"
    cp "$out/sweep.toml" "$archive.part/" 2>/dev/null || true
    each_point save_folder "$out" "$archive.part"
    rm -rf "$archive"
    mv "$archive.part" "$archive"
    done=$(find "$archive/points" -mindepth 2 -maxdepth 2 -name summary.json | wc -l)
    echo "study-archive: $archive: $(find "$archive/points" -mindepth 1 -maxdepth 1 | wc -l) point folders," \
      "$done finished, $(du -sh "$archive" | cut -f1)"
    ;;
  restore)
    [[ -d $archive/points ]] || {
      echo "study-archive: $archive/points: no such folder (nothing saved)" >&2
      exit 2
    }
    refuse_if_running
    each_point restore_folder "$archive" "$out"
    echo "study-archive: restored $archive into $out"
    ;;
  *) usage ;;
esac
