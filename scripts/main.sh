#!/usr/bin/env bash
# The main job, from nothing: install dependencies, build, and run the built-in
# default shear cell (the paper's cell at phi 0.58, mu0 0.1, lambda 100; a few
# minutes on 2 cores). Results: out/default/ (summary.json, timeseries.csv,
# velocity_profile.csv, sommerfeld_hist.csv, contacts.csv, cell.pvd for ParaView).
# Extra arguments go to `dilatant run`, e.g. --set friction.mu0=0.3
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
bash scripts/install-deps.sh
# The run needs the `dilatant` executable only; the tests, benchmarks and Python
# module build with `bash scripts/build.sh` (all of build/) or scripts/test.sh.
bash scripts/build.sh release dilatant
# All cores for this one run (results do not depend on the thread count).
./build/dilatant run --out out/default --set solver.threads=0 "$@"
