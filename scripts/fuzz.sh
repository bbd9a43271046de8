#!/usr/bin/env bash
# Builds the libFuzzer targets (fuzz/, clang with ASan + UBSan) in the sanitizer
# tree, build-sanitize/ (scripts/build.sh sanitize: the same build serves the
# ASan + UBSan tests), and runs each for SECONDS (default 60) of a core, as
# many at once as there are cores (below: a last round's target on all cores).
#   scripts/fuzz.sh [SECONDS] [TARGET ...]   targets: config particles_csv checkpoint
#                                            rheometer_file predict_tables (default: all five)
# Each starts from its committed seeds (fuzz/corpus/TARGET/) copied into
# build-sanitize/fuzz/corpus/TARGET/, where the inputs that reach new code accumulate
# across runs. A crash, sanitizer report, leak, timeout (10 s an input) or memory
# blow-up (2 GiB) stops that target, leaves the input in
# build-sanitize/fuzz/artifacts/TARGET/ and makes this script exit 1; to keep it as a
# regression, copy it into fuzz/crashes/TARGET/ (tests/fuzz/ replays those and the
# corpus in every build). Executions and coverage per target are appended to
# build-sanitize/fuzz/fuzz-stats.txt. docs/reliability.md "Fuzzing" has the numbers.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
seconds=${1:-60}
shift $(($# > 0))
targets=("$@")
if ((${#targets[@]} == 0)); then targets=(config particles_csv checkpoint rheometer_file predict_tables); fi

bash scripts/install-deps.sh
dir=build-sanitize
bash scripts/build.sh sanitize "${targets[@]/%/_fuzzer}"

export ASAN_OPTIONS=detect_leaks=1:allocator_may_return_null=1
export UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1
# fuzz_one TARGET SECONDS [PART]: SECONDS of libFuzzer on one core; its
# statistics line goes to fuzz-stats.txt; exit 1 if it found something. PART
# names one of several processes fuzzing TARGET at once (its own log; they
# share the corpus folder, as libFuzzer's own -jobs do).
fuzz_one() {
  local target=$1 time=$2 part=${3:-} status=0
  local corpus=$dir/fuzz/corpus/$target artifacts=$dir/fuzz/artifacts/$target
  local log=$dir/fuzz/$target${part:+.$part}.log
  mkdir -p "$corpus" "$artifacts"
  cp -n fuzz/corpus/"$target"/* "$corpus"/ 2>/dev/null || true
  echo "=== fuzz.sh: $target${part:+ (part $part)} for $time s"
  if ! "$dir/fuzz/${target}_fuzzer" "$corpus" -max_total_time="$time" -timeout=10 \
    -rss_limit_mb=2048 -print_final_stats=1 -artifact_prefix="$artifacts/" >"$log" 2>&1; then
    status=1
    echo "=== fuzz.sh: $target FAILED; its input is in $artifacts/, the report in $log" >&2
    grep -E "ERROR|SUMMARY|==[0-9]+==" "$log" | head -20 >&2 || true
  fi
  local runs cov
  runs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$' || echo 0)
  cov=$(grep -o 'cov: [0-9]*' "$log" | tail -1 | grep -o '[0-9]*' || echo 0)
  printf '%s\t%s\t%s s\t%s executions\tcoverage %s\t%s inputs in corpus\n' "$(date -u +%FT%TZ)" \
    "$target${part:+ part $part}" "$time" "$runs" "$cov" "$(find "$corpus" -type f | wc -l)" |
    tee -a "$dir/fuzz/fuzz-stats.txt"
  return "$status"
}

# Whole rounds of one target per core: each gets SECONDS of a core of its own
# (libFuzzer runs one process). A last round with fewer targets than cores
# would leave cores idle, so there each of its targets runs as cores / left
# processes at once on its corpus, SECONDS / that each: the same SECONDS of
# fuzzing a target, and the whole takes SECONDS x targets / cores (5 targets on
# 2 cores: 75 s instead of three rounds' 90).
cores=$(nproc)
rounds=$((${#targets[@]} / cores * cores))
status=0
pids=()
for target in "${targets[@]:0:rounds}"; do
  fuzz_one "$target" "$seconds" &
  pids+=($!)
  if ((${#pids[@]} >= cores)); then
    wait "${pids[0]}" || status=1
    pids=("${pids[@]:1}")
  fi
done
for pid in "${pids[@]}"; do wait "$pid" || status=1; done
left=("${targets[@]:rounds}")
pids=()
if ((${#left[@]} > 0)); then
  parts=$((cores / ${#left[@]}))
  for target in "${left[@]}"; do
    for ((part = 1; part <= parts; part++)); do
      fuzz_one "$target" $(((seconds + parts - 1) / parts)) "$( ((parts > 1)) && echo "$part")" &
      pids+=($!)
    done
  done
fi
for pid in "${pids[@]}"; do wait "$pid" || status=1; done
exit "$status"
