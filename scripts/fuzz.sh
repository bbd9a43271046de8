#!/usr/bin/env bash
# Builds the libFuzzer targets (fuzz/, clang with ASan + UBSan) in build-fuzz/ and
# runs each for SECONDS (default 60), one after another, on one core.
#   scripts/fuzz.sh [SECONDS] [TARGET ...]   targets: config particles_csv checkpoint
#                                            rheometer_file (default: all four)
# Each starts from its committed seeds (fuzz/corpus/TARGET/) copied into
# build-fuzz/corpus/TARGET/, where the inputs that reach new code accumulate
# across runs. A crash, sanitizer report, leak, timeout (10 s an input) or memory
# blow-up (2 GiB) stops that target, leaves the input in
# build-fuzz/artifacts/TARGET/ and makes this script exit 1; to keep it as a
# regression, copy it into fuzz/crashes/TARGET/ (tests/fuzz/ replays those and the
# corpus in every build). Executions and coverage per target are appended to
# build-fuzz/fuzz-stats.txt. docs/reliability.md "Fuzzing" has the numbers.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
seconds=${1:-60}
shift $(($# > 0))
targets=("$@")
if ((${#targets[@]} == 0)); then targets=(config particles_csv checkpoint rheometer_file); fi

bash scripts/install-deps.sh
dir=build-fuzz
# Warnings are g++'s business (scripts/build.sh); clang's differ in detail.
cmake -S . -B "$dir" -G Ninja -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DDILATANT_SANITIZE=ON -DDILATANT_BUILD_FUZZERS=ON -DDILATANT_WERROR=OFF -DBUILD_TESTING=OFF \
  -DDILATANT_BUILD_BENCHMARKS=OFF -DDILATANT_BUILD_PYTHON=OFF -DDILATANT_WITH_MPI=OFF >/dev/null
cmake --build "$dir" --parallel "$(nproc)" --target "${targets[@]/%/_fuzzer}"

export ASAN_OPTIONS=detect_leaks=1:allocator_may_return_null=1
export UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1
status=0
for target in "${targets[@]}"; do
  corpus=$dir/corpus/$target artifacts=$dir/artifacts/$target
  mkdir -p "$corpus" "$artifacts"
  cp -n fuzz/corpus/"$target"/* "$corpus"/ 2>/dev/null || true
  log=$dir/$target.log
  echo "=== fuzz.sh: $target for $seconds s"
  if ! "$dir/fuzz/${target}_fuzzer" "$corpus" -max_total_time="$seconds" -timeout=10 \
    -rss_limit_mb=2048 -print_final_stats=1 -artifact_prefix="$artifacts/" >"$log" 2>&1; then
    status=1
    echo "=== fuzz.sh: $target FAILED; its input is in $artifacts/, the report in $log" >&2
    grep -E "ERROR|SUMMARY|==[0-9]+==" "$log" | head -20 >&2 || true
  fi
  runs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$' || echo 0)
  cov=$(grep -o 'cov: [0-9]*' "$log" | tail -1 | grep -o '[0-9]*' || echo 0)
  printf '%s\t%s\t%s s\t%s executions\tcoverage %s\t%s inputs in corpus\n' "$(date -u +%FT%TZ)" \
    "$target" "$seconds" "$runs" "$cov" "$(find "$corpus" -type f | wc -l)" | tee -a "$dir/fuzz-stats.txt"
done
exit "$status"
