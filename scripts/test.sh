#!/usr/bin/env bash
# Everything CI checks, in order: packages, release build + tests, sanitizer
# build (ASan + UBSan, which also holds the fuzz targets) + tests,
# ThreadSanitizer, fuzzing (30 s a reader), formatting, layers, docs tables.
# Later stages still run after a failure so one run shows every problem; the exit status is
# non-zero if any stage failed. At the end: each stage's wall time and the
# slowest tests (build/test-report.md). docs/testing.md says what each stage
# checks and why.
#   scripts/test.sh            (DILATANT_SKIP_DEPS=1 skips the apt step)
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

jobs=$(nproc)
failed=()
# Each stage's wall time, for the table printed at the end (build/test-report.md).
mkdir -p build
times=build/test-stages.tsv
: >"$times"
# stage NAME COMMAND...: runs COMMAND, records its wall time, and NAME if it
# fails; returns its status.
stage() {
  local name=$1 start=$SECONDS status=0
  shift
  echo "=== test.sh: $name"
  "$@" || status=$?
  printf '%s\t%s\t%s\n' "$name" $((SECONDS - start)) "$( ((status == 0)) && echo ok || echo FAILED)" >>"$times"
  if ((status == 0)); then return 0; fi
  failed+=("$name")
  echo "=== test.sh: $name FAILED" >&2
  return 1
}
# ctest_logged TREE COSTS [ARGS...]: ctest in TREE, its output kept for the
# report (ctest's own per-test timing). ctest starts the tests it knows to be
# longest first, from the times it recorded in the tree; a fresh tree has none,
# and the long ones would start last and run alone at the end. So a fresh tree
# gets the committed times of a reference run (tests/ctest-costs/COSTS.txt;
# refresh: copy TREE/Testing/Temporary/CTestCostData.txt there, without the
# failed-test list after its "---").
ctest_logged() {
  local tree=$1 costs=tests/ctest-costs/$2.txt
  shift 2
  mkdir -p "$tree/Testing/Temporary"
  if [[ ! -f $tree/Testing/Temporary/CTestCostData.txt ]]; then
    cp "$costs" "$tree/Testing/Temporary/CTestCostData.txt"
  fi
  ctest --test-dir "$tree" "$@" 2>&1 | tee "$tree/ctest.log"
}

stage "packages" bash scripts/install-deps.sh || exit 1
# install-deps.sh installed matplotlib: the CLI tests must see the figures drawn.
export DILATANT_REQUIRE_PLOTS=1

# python_bindings (pytest over python/tests with the tree's module) is left to
# the pip stage below, which runs the same tests against the installed package
# (and the three that need it installed): 28 s of a core once, not twice.
if stage "release build" bash scripts/build.sh release; then
  stage "release tests" ctest_logged build release --output-on-failure --no-tests=error -j "$jobs" \
    -E '^python_bindings$' || true
fi

# `pip install .` into a fresh venv, and the Python tests against the installed
# package (docs/python.md "Install with pip").
stage "pip install" bash scripts/pip-check.sh || true

# Stop at the first sanitizer report. detect_leaks=1 is checked to work here: at exit
# LeakSanitizer suspends the threads with ptrace; where ptrace is forbidden (some
# containers, or under gdb/strace) it aborts instead, and detect_leaks=0 is needed.
# Exported before the build: gtest_discover_tests runs the instrumented tests then.
export ASAN_OPTIONS=halt_on_error=1:abort_on_error=1:detect_leaks=1
export UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1
if stage "sanitize build" bash scripts/build.sh sanitize; then
  # The long tests that run the same lines of src/ as the short ones, only
  # longer (seed averages, a sediment settled to rest), are left to the release
  # stage: tests/sanitize/release-only.txt, and scripts/coverage-proof.sh shows
  # that the tests kept here run every line of src/ that they run.
  release_only="^($(grep -vE '^\s*(#|$)' tests/sanitize/release-only.txt | paste -sd'|'))\$"
  stage "sanitize tests" ctest_logged build-sanitize sanitize --output-on-failure --no-tests=error \
    -j "$jobs" -E "$release_only" || true
fi

# The sanitizer tree leaves three UBSan checks out of Eigen's headers
# (cmake/ubsan-ignorelist.txt); the probe, built in that tree with its own
# flags, shows each fault they guarded still reported
# (tests/sanitize/eigen_ignorelist_probe.cpp).
ignorelist_probe() {
  local exe=build-sanitize/tests/eigen_ignorelist_probe fault
  [[ -x $exe ]] || { echo "ignorelist probe: $exe was not built" >&2; return 1; }
  for fault in 1 2 3 4; do
    if ("$exe" "$fault") 2>"$exe.$fault.log" ||
      ! grep -qE "runtime error|ERROR: AddressSanitizer|Assertion" "$exe.$fault.log"; then
      echo "ignorelist probe: fault $fault was not reported ($exe.$fault.log)" >&2
      return 1
    fi
  done
  echo "ignorelist probe: the four faults reported"
}
stage "sanitize probe" ignorelist_probe || true

# ThreadSanitizer over the threaded suites (clang, LLVM's OpenMP with Archer;
# docs/reliability.md "Sanitizers").
stage "tsan" bash scripts/tsan.sh || true

# The readers of user input under libFuzzer (clang, ASan + UBSan), 30 s each
# from the committed seeds (docs/reliability.md "Fuzzing").
stage "fuzz" bash scripts/fuzz.sh 30 || true

format_check() {
  find src tests bench fuzz python/src -type f \( -name '*.cpp' -o -name '*.hpp' -o -name '*.h' \) -print0 |
    xargs -0 --no-run-if-empty clang-format --dry-run --Werror
}
stage "clang-format" format_check || true
# Every folder of src/ includes only lower layers (docs/architecture.md); the
# checker first shows on a made-up tree that it reads every spelling.
layers_check() { python3 scripts/check-layers.py --self-test && python3 scripts/check-layers.py src; }
stage "layers" layers_check || true
# Each test file's code in a namespace of its own: the tests build in unity
# batches whose make-up changes as files are added (scripts/build.sh).
stage "test namespaces" python3 scripts/check-test-namespaces.py || true
# The docs tell users to run scripts/NAME.sh directly: each one tracked
# executable (a 644 script fails with "Permission denied").
script_modes_check() {
  local bad
  bad=$(git ls-files -s 'scripts/*.sh' | awk '$1 != "100755" {print $4}')
  [[ -z $bad ]] || { echo "not executable in git (git update-index --chmod=+x): $bad"; return 1; }
}
stage "script modes" script_modes_check || true
# Every docs table and prose number with a source marker agrees with the
# committed CSV/JSON it names (docs/testing.md "Docs against their data"); the
# checker first shows on made-up pages that it reports a disagreement.
docs_check() { python3 scripts/check-docs-tables.py --self-test && python3 scripts/check-docs-tables.py; }
stage "docs tables" docs_check || true

python3 scripts/test_report.py "$times" release=build/ctest.log sanitize=build-sanitize/ctest.log \
  tsan=build-tsan/tsan.log >build/test-report.md || true
echo "=== test.sh: wall time per stage, slowest tests (build/test-report.md)"
cat build/test-report.md

if ((${#failed[@]} > 0)); then
  printf '=== test.sh: FAILED: %s\n' "$(IFS=,; echo "${failed[*]}")" >&2
  exit 1
fi
echo "=== test.sh: all stages passed"
