#!/usr/bin/env bash
# Shared by the bench/ study scripts (jam_creep.sh, tolerance_study.sh,
# solve_problems.sh, redo_problems.sh,
# accuracy_guard.sh): their common options and a queue of runs side by side.
# Source it from a script that has cd'ed to the repository root.

# parse_study_args SCRIPT_NAME ARGS...: sets label, binary, jobs, report_only
# from --label L, --binary PATH, --jobs N, --report-only; exits 2 on anything else.
parse_study_args() {
  local name=$1
  shift
  label=$(date +%Y%m%d) binary=build/dilatant jobs=2 report_only=0
  while (($# > 0)); do
    case "$1" in
      --label) label=$2; shift 2 ;;
      --binary) binary=$2; shift 2 ;;
      --jobs) jobs=$2; shift 2 ;;
      --report-only) report_only=1; shift ;;
      *) echo "usage: $name [--label L] [--binary PATH] [--jobs N] [--report-only]" >&2; exit 2 ;;
    esac
  done
}

# parse_problem_args SCRIPT_NAME DEFAULT_GROUPS ARGS...: for the scripts that
# solve the dumped step problems again (solve_problems.sh, redo_problems.sh):
# sets problems, label, groups from --problems DIR, --label L, --groups "A ...";
# exits 2 on anything else, 1 without DIR/MANIFEST.csv (bench/dump_problems.sh).
parse_problem_args() {
  local name=$1
  problems=bench/problems label=$(date +%Y%m%d) groups=$2
  shift 2
  while (($# > 0)); do
    case "$1" in
      --problems) problems=$2; shift 2 ;;
      --label) label=$2; shift 2 ;;
      --groups) groups=$2; shift 2 ;;
      *) echo "usage: $name [--problems DIR] [--label L] [--groups \"A B1 ...\"]" >&2; exit 2 ;;
    esac
  done
  [[ -f "$problems/MANIFEST.csv" ]] ||
    { echo "$name: no $problems/MANIFEST.csv (bench/dump_problems.sh)" >&2; exit 1; }
}

# queue_run COMMAND...: starts COMMAND in the background once fewer than $jobs
# runs are going (call `wait` after the last one).
queue_run() {
  while (($(jobs -rp | wc -l) >= jobs)); do sleep 1; done
  "$@" &
}
