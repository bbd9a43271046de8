#!/usr/bin/env bash
# The proof behind the tests the sanitizer stages leave out
# (tests/sanitize/release-only.txt for ASan + UBSan, tests/tsan/release-only.txt
# for ThreadSanitizer): from a line-coverage build (scripts/build.sh coverage),
# the lines of src/ that the left-out tests run, against those that the tests
# left in the stage run. Exit 0 if the left-out tests run no line of src/ that
# the others do not; otherwise the lines, and exit 1. Not part of CI (a
# coverage build and two runs of the suite, 35 minutes on 2 idle cores): run
# it when a list changes, or when a listed test starts to run new code.
# docs/testing.md, "Fourth round".
#   scripts/coverage-proof.sh [sanitize|tsan]   (default: both)
# A line counts as run if any process ran it: the test executable and every
# `dilatant` it started (LLVM_PROFILE_FILE with %p, one profile a process).
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

stages=("$@")
if ((${#stages[@]} == 0)); then stages=(sanitize tsan); fi
for stage in "${stages[@]}"; do
  if [[ $stage != sanitize && $stage != tsan ]]; then
    echo "$0: unknown stage '$stage' (sanitize or tsan)" >&2
    exit 2
  fi
done

# The build runs the test executable once to list its tests: its profile is
# of no use.
LLVM_PROFILE_FILE=/dev/null bash scripts/build.sh coverage dilatant dilatant_tests
tree=build-coverage
tests=$tree/tests/dilatant_tests
export DILATANT_REQUIRE_PLOTS=1 # as scripts/test.sh: the plot paths run too

# names FILE: the list's names, one a line, comments and blank lines dropped.
names() { grep -vE '^\s*(#|$)' "$1"; }
# profile NAME COMMAND...: runs COMMAND with every process profiled into
# $tree/proof/NAME/, then merges the profiles into $tree/proof/NAME.profdata
# and exports its line counts (lcov) to $tree/proof/NAME.lcov.
profile() {
  local name=$1 dir=$tree/proof/$1
  shift
  rm -rf "$dir" && mkdir -p "$dir"
  echo "=== coverage-proof.sh: $name"
  # A test failing here is the other stages' business, and some fail only
  # because of the profiling (the tests that cap the file size or make the
  # output read-only also stop the profile's own write): the lines they run
  # then count as not run, which can only make the proof stricter.
  LLVM_PROFILE_FILE="$PWD/$dir/%p.profraw" "$@" >"$dir.log" 2>&1 ||
    echo "coverage-proof.sh: some tests of '$name' failed in the coverage build (see $dir.log)"
  # -failure-mode=all: a profile cut short by such a test is skipped.
  llvm-profdata merge -sparse -failure-mode=all "$dir"/*.profraw -o "$dir.profdata"
  llvm-cov export -format=lcov -instr-profile="$dir.profdata" "$tests" \
    -object "$tree/dilatant" >"$dir.lcov"
  rm -rf "$dir"
}

status=0
for stage in "${stages[@]}"; do
  list=tests/$stage/release-only.txt
  mapfile -t left < <(names "$list")
  if [[ $stage == sanitize ]]; then
    # As scripts/test.sh runs the stage: ctest over the whole suite.
    regex="^($(IFS='|'; echo "${left[*]}"))\$"
    profile sanitize-kept ctest --test-dir "$tree" -j "$(nproc)" -E "$regex"
    profile sanitize-left ctest --test-dir "$tree" -j "$(nproc)" -R "$regex"
  else
    # As scripts/tsan.sh runs the stage: its suites, in one process here.
    mapfile -t suites < <(bash scripts/tsan.sh --print-suites)
    kept=$(printf '%s.*:' "${suites[@]}")
    negative=$(IFS=':'; echo "${left[*]}")
    profile tsan-kept "$tests" --gtest_filter="${kept%:}-$negative"
    profile tsan-left "$tests" --gtest_filter="$negative"
  fi
  python3 scripts/coverage_difference.py --source src \
    "$tree/proof/$stage-kept.lcov" "$tree/proof/$stage-left.lcov" "$list" || status=1
done
exit "$status"
