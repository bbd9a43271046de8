#!/usr/bin/env bash
# Configures and builds dilatant with Ninja on all cores.
#   scripts/build.sh [release|sanitize|tsan] [target...]   (default: release, all targets)
#     release  -> build/           Release; CLI, tests, benchmarks, Python module (build/python)
#     sanitize -> build-sanitize/  RelWithDebInfo with ASan + UBSan; no benchmarks, no
#                                  Python module (an ASan extension loads only with LD_PRELOAD),
#                                  no MPI (LeakSanitizer reports Open MPI's own ~120 kB of
#                                  allocations left at MPI_Finalize, even for an empty
#                                  program; docs/cluster.md): the MPI tests skip there
#     tsan     -> build-tsan/      RelWithDebInfo with ThreadSanitizer, clang (OpenMP is
#                                  then LLVM's libomp, whose Archer tool tells TSan about
#                                  OpenMP's barriers; scripts/tsan.sh runs it); no
#                                  benchmarks, no Python module, no MPI (as sanitize)
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

case "${1:-release}" in
  release)
    dir=build
    options=(-DCMAKE_BUILD_TYPE=Release -DDILATANT_SANITIZE=OFF -DDILATANT_BUILD_BENCHMARKS=ON
      -DDILATANT_BUILD_PYTHON=ON)
    ;;
  sanitize)
    dir=build-sanitize
    options=(-DCMAKE_BUILD_TYPE=RelWithDebInfo -DDILATANT_SANITIZE=ON
      -DDILATANT_BUILD_BENCHMARKS=OFF -DDILATANT_BUILD_PYTHON=OFF -DDILATANT_WITH_MPI=OFF)
    ;;
  tsan)
    dir=build-tsan
    # Warnings are g++'s business (release, sanitize); clang's differ in detail.
    options=(-DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=RelWithDebInfo -DDILATANT_TSAN=ON
      -DDILATANT_WERROR=OFF -DDILATANT_BUILD_BENCHMARKS=OFF -DDILATANT_BUILD_PYTHON=OFF
      -DDILATANT_WITH_MPI=OFF)
    ;;
  *)
    echo "usage: $0 [release|sanitize|tsan] [target...]" >&2
    exit 2
    ;;
esac

shift $(($# > 0))  # the rest, if any, are targets (e.g. solver_sweep_bench)
targets=()
if (($# > 0)); then targets=(--target "$@"); fi

cmake -S . -B "$dir" -G Ninja "${options[@]}"
cmake --build "$dir" --parallel "$(nproc)" "${targets[@]}"
