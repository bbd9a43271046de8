#!/usr/bin/env bash
# Builds the release tree and runs the solver benchmark; extra arguments go to
# Google Benchmark, e.g.  scripts/bench.sh --benchmark_repetitions=5
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
bash scripts/install-deps.sh
bash scripts/build.sh release
./build/bench/solver_sweep_bench "$@"
