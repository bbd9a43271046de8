#!/usr/bin/env bash
# Builds the solver benchmark in the release tree (build/) and runs it; extra
# arguments go to Google Benchmark, e.g.  scripts/bench.sh --benchmark_repetitions=5
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
bash scripts/install-deps.sh
bash scripts/build.sh release solver_sweep_bench
./build/bench/solver_sweep_bench "$@"
