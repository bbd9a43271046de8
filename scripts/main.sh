#!/usr/bin/env bash
# The main job, from nothing: install dependencies, build, and run the shipped
# example (a pile of 300 frictional spheres settling in a box).
# Results: out/pile/ (summary.json, trajectory.csv, contacts.csv, ...).
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
bash scripts/install-deps.sh
bash scripts/build.sh release
./build/dilatant run examples/pile/pile.toml --out out/pile "$@"
