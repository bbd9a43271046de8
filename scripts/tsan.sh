#!/usr/bin/env bash
# ThreadSanitizer over the threaded code: the OpenMP contact solver, detection
# and time stepper (one thread per core in every shear-cell run that sets none,
# 2 where a test compares thread counts, 3 in the numerical-fault tests) and the
# sweep's worker threads (jobs = 2, in the test process and in the CLI the tests
# start). Builds build-tsan/ (scripts/build.sh
# tsan: clang, LLVM's libomp), only the CLI and the executable of the threaded
# suites' files (tests/CMakeLists.txt, dilatant_threaded_tests), and runs the
# suites below in two processes side by side, stopping at the first report
# (docs/reliability.md "Sanitizers").
#   scripts/tsan.sh [GTEST_FILTER]
#   scripts/tsan.sh --print-suites     the suites, one a line (coverage-proof.sh)
# OpenMP's barriers are invisible to TSan unless LLVM's Archer tool is loaded
# into libomp: OMP_TOOL_LIBRARIES names it, and the run fails unless Archer says
# it is active in a probe run (a TSan run without it would report the barriers
# as races, and one where it silently failed to load would prove nothing).
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

# The threaded suites. Everything else runs single-threaded code (parsers,
# analysis, closed-form scenes) that ASan + UBSan already cover; the long
# seed-averaged physics suites run the same threaded code as ShearCellRun.
# They run as two processes side by side (each test already uses two threads,
# but a run leaves cores idle between its OpenMP regions and in the CLI's
# start-up): on an idle 2-core machine 195 s in one process, 114 s as two
# halves, split by measured time. The halves are split again from the CI run
# of 7b07d55 (197 s of tests): RampToJam's longest test (76 s) leads the first
# half, SweepRunner 15 + small ones after it (96 s in all), against RampToJam's
# other tests 36 + SweepCommand 38 + LeesEdwardsCell 11 + ShearCellFluid 6 +
# RampRefinement 4 + ShearCellRun 4 + small ones (101 s); the split before
# (RampToJam whole in the first half) took 132 s against 65.
long_test=RampToJam.StopsAtTheFirstJamAndConfirmsItFromAColdStart
half_a=(SweepRunner Checkpoint ShearCellObject ContactResidual UnconvergedRun NumericalFault)
half_b=(RampToJam SweepCommand LeesEdwardsCell ShearCellRun ShearCellFluid ContactDetector Stopping
  RampRefinement)
suites=("${half_a[@]}" "${half_b[@]}")
if [[ ${1:-} == --print-suites ]]; then
  printf '%s\n' "${suites[@]}"
  exit 0
fi
# Their long tests that run no line of src/ the others do not run, left to
# the release stage (tests/tsan/release-only.txt; scripts/coverage-proof.sh).
release_only=$(grep -vE '^\s*(#|$)' tests/tsan/release-only.txt | paste -sd:)
suites_of() { local f; f=$(printf '%s.*:' "$@"); echo "${f%:}"; }
# One GTEST_FILTER instead runs those tests in one process.
filters=("$long_test:$(suites_of "${half_a[@]}")-$release_only"
  "$(suites_of "${half_b[@]}")-$release_only:$long_test")
if (($# > 0)); then filters=("$1"); fi

bash scripts/install-deps.sh
bash scripts/build.sh tsan dilatant dilatant_threaded_tests
tests=build-tsan/tests/dilatant_threaded_tests

# Every suite named here must be in that executable: a suite whose file is
# missing from its list would otherwise pass by running nothing.
listed=$("$tests" --gtest_list_tests)
for suite in "${suites[@]}"; do
  if ! grep -qE "^$suite\.\$" <<<"$listed"; then
    echo "tsan.sh: suite $suite is not in $tests: add its file to tests/CMakeLists.txt" >&2
    exit 1
  fi
done
if ! "$tests" --gtest_filter="$long_test" --gtest_list_tests | grep -qE "^  ${long_test#*.}\$"; then
  echo "tsan.sh: the first half's lead test $long_test is not in $tests: rename it here" >&2
  exit 1
fi

llvm_lib=$(dirname "$(readlink -f "$(command -v clang++)")")/../lib
archer=$(readlink -f "$llvm_lib/libarcher.so")
if [[ ! -f $archer ]]; then
  echo "tsan.sh: LLVM's Archer ($llvm_lib/libarcher.so) not found; install libomp-dev" >&2
  exit 1
fi
export OMP_TOOL_LIBRARIES=$archer
# ignore_noninstrumented_modules: libomp itself is not built with TSan; its
# internals (the lock it initialises in a worker and takes in the main thread)
# would be reported. The suites start the CLI (built with TSan too): a report
# there fails that test through the exit status 66.
export TSAN_OPTIONS=halt_on_error=1:exitcode=66:second_deadlock_stack=1:ignore_noninstrumented_modules=1

# First, that Archer is loaded: one two-thread cell, Archer verbose. (Verbose
# only here: the CLI tests want an empty stderr.)
probe=ShearCellRun.TwoThreadsGiveTheSameBitsAsOne
mkdir -p build-tsan
ARCHER_OPTIONS=verbose=1 "$tests" --gtest_filter="$probe" \
  >build-tsan/archer-probe.log 2>&1 || true
if ! grep -q "Archer detected OpenMP application" build-tsan/archer-probe.log; then
  echo "tsan.sh: Archer did not load into libomp ($archer): OpenMP barriers would be unseen" >&2
  exit 1
fi

# Then that this set-up sees a race in an OpenMP loop and none across a
# barrier (tests/tsan/openmp_race_probe.cpp: a race on line 12, none on 18 and 21).
clang++ -fsanitize=thread -fopenmp -g -O1 tests/tsan/openmp_race_probe.cpp \
  -o build-tsan/openmp_race_probe
TSAN_OPTIONS=${TSAN_OPTIONS/halt_on_error=1:/} build-tsan/openmp_race_probe \
  >build-tsan/race-probe.log 2>&1 || true
if ! grep -q "openmp_race_probe.cpp:12" build-tsan/race-probe.log ||
  grep -qE "openmp_race_probe.cpp:(18|21):" build-tsan/race-probe.log; then
  echo "tsan.sh: the race probe was not seen as expected (build-tsan/race-probe.log)" >&2
  exit 1
fi

log=build-tsan/tsan.log
pids=()
for i in "${!filters[@]}"; do
  echo "=== tsan.sh: ${filters[$i]}"
  "$tests" --gtest_filter="${filters[$i]}" >"$log.$i" 2>&1 &
  pids+=($!)
done
status=0
for pid in "${pids[@]}"; do wait "$pid" || status=$?; done
cat "$log".* >"$log"
rm -f "$log".*
grep -E "^\[ *(OK|FAILED|PASSED) *\]" "$log" || true
if grep -q "WARNING: ThreadSanitizer" "$log"; then
  grep -A30 "WARNING: ThreadSanitizer" "$log" | head -40 >&2
  echo "tsan.sh: ThreadSanitizer reported (the whole report is in $log)" >&2
  exit 1
fi
exit "$status"
