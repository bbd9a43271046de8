#!/usr/bin/env bash
# Configures and builds dilatant with Ninja on all cores.
#   scripts/build.sh [release|sanitize]     (default: release)
#     release  -> build/           Release; CLI, tests and benchmarks
#     sanitize -> build-sanitize/  RelWithDebInfo with ASan + UBSan; no benchmarks
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

case "${1:-release}" in
  release)
    dir=build
    options=(-DCMAKE_BUILD_TYPE=Release)
    ;;
  sanitize)
    dir=build-sanitize
    options=(-DCMAKE_BUILD_TYPE=RelWithDebInfo -DDILATANT_SANITIZE=ON
      -DDILATANT_BUILD_BENCHMARKS=OFF)
    ;;
  *)
    echo "usage: $0 [release|sanitize]" >&2
    exit 2
    ;;
esac

cmake -S . -B "$dir" -G Ninja "${options[@]}"
cmake --build "$dir" --parallel "$(nproc)"
