#!/usr/bin/env bash
# Configures and builds dilatant with Ninja on all cores.
#   scripts/build.sh [release|sanitize|tsan|coverage] [target...]   (default: release, all targets)
#     release  -> build/           Release (g++, warnings are errors); CLI, tests,
#                                  benchmarks, Python module (build/python)
#     sanitize -> build-sanitize/  ASan + UBSan (clang); the CLI, the tests and the
#                                  libFuzzer targets (scripts/fuzz.sh) in one tree:
#                                  the library and the fuzz harness also carry
#                                  libFuzzer's coverage. No benchmarks, no Python
#                                  module (an ASan extension loads only with
#                                  LD_PRELOAD), no MPI (LeakSanitizer reports Open
#                                  MPI's own ~120 kB of allocations left at
#                                  MPI_Finalize, even for an empty program;
#                                  docs/cluster.md): the MPI tests skip there
#     tsan     -> build-tsan/      ThreadSanitizer (clang; OpenMP is then LLVM's
#                                  libomp, whose Archer tool tells TSan about OpenMP's
#                                  barriers; scripts/tsan.sh runs it); the CLI and
#                                  the threaded suites' executable only are meant
#                                  to be built there (scripts/tsan.sh names them)
#     coverage -> build-coverage/  clang's source-based line coverage, the
#                                  sanitizer trees' other settings; for
#                                  scripts/coverage-proof.sh, not CI
# The sanitizer trees build with -O1 and line tables only: what a sanitizer
# report needs (file:line in every frame), at a fraction of full -g's compile
# time. Warnings are g++'s business (release); clang's differ in detail.
#
# Release and sanitize are unity builds: CMake compiles the sources of a target
# in batches of 16, one translation unit a batch, so the templates every file
# instantiates (GoogleTest's, Eigen's, fmt's, JSON's, std::string's) are
# compiled once a batch instead of once a file: the release tree's compile 1,299
# CPU-seconds file by file, about 650 in batches of 8, about 500 in batches of
# 16 (docs/testing.md, "Third round"). Each test file keeps its helpers in a
# namespace named after the file (dilatant::incline_test) so that two files'
# helpers never meet in a batch. An edit-compile loop rebuilds a whole batch:
#   DILATANT_UNITY=OFF scripts/build.sh     compiles each source alone.
# The tsan tree batches its tests but compiles each source of the library and
# the CLI alone (DILATANT_SOURCES_ALONE), which also checks that every one of
# them includes what it uses.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

unity=${DILATANT_UNITY:-ON}
if [[ $unity != ON && $unity != OFF ]]; then
  echo "$0: DILATANT_UNITY must be ON or OFF, not '$unity'" >&2
  exit 2
fi
sanitizer_tree=(-DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=RelWithDebInfo
  "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -gline-tables-only" -DDILATANT_WERROR=OFF
  -DDILATANT_BUILD_BENCHMARKS=OFF -DDILATANT_BUILD_PYTHON=OFF -DDILATANT_WITH_MPI=OFF)
case "${1:-release}" in
  release)
    dir=build
    options=(-DCMAKE_BUILD_TYPE=Release -DDILATANT_SANITIZE=OFF -DDILATANT_BUILD_BENCHMARKS=ON
      -DDILATANT_BUILD_PYTHON=ON -DCMAKE_UNITY_BUILD="$unity" -DCMAKE_UNITY_BUILD_BATCH_SIZE=16)
    ;;
  sanitize)
    dir=build-sanitize
    options=("${sanitizer_tree[@]}" -DDILATANT_SANITIZE=ON -DDILATANT_BUILD_FUZZERS=ON
      -DCMAKE_UNITY_BUILD="$unity" -DCMAKE_UNITY_BUILD_BATCH_SIZE=16)
    ;;
  tsan)
    dir=build-tsan
    options=("${sanitizer_tree[@]}" -DDILATANT_TSAN=ON -DCMAKE_UNITY_BUILD=ON
      -DCMAKE_UNITY_BUILD_BATCH_SIZE=16 -DDILATANT_SOURCES_ALONE=ON)
    ;;
  coverage)
    dir=build-coverage
    options=("${sanitizer_tree[@]}" -DDILATANT_COVERAGE=ON -DCMAKE_UNITY_BUILD="$unity"
      -DCMAKE_UNITY_BUILD_BATCH_SIZE=16)
    ;;
  *)
    echo "usage: $0 [release|sanitize|tsan|coverage] [target...]" >&2
    exit 2
    ;;
esac

shift $(($# > 0))  # the rest, if any, are targets (e.g. solver_sweep_bench)
targets=()
if (($# > 0)); then targets=(--target "$@"); fi

cmake -S . -B "$dir" -G Ninja "${options[@]}"
cmake --build "$dir" --parallel "$(nproc)" "${targets[@]}"
