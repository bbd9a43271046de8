#!/usr/bin/env bash
# Installs every Debian package dilatant needs (tested on Debian 12), non-interactively.
#   scripts/install-deps.sh [extra-package ...]   (e.g. python3-matplotlib for docs figures)
# Does nothing (no network, no root needed) when all packages are already installed
# or when DILATANT_SKIP_DEPS=1. Uses sudo when not run as root.
set -euo pipefail

packages=(
  g++ cmake ninja-build pkg-config                  # toolchain
  libgtest-dev libgmock-dev libbenchmark-dev        # tests and benchmarks
  libcli11-dev libtomlplusplus-dev nlohmann-json3-dev libeigen3-dev libfmt-dev  # libraries
  zlib1g-dev                                        # CRC-32 of checkpoints
  python3 python3-numpy python3-matplotlib python3-vtk9  # figures and post-processing scripts
  python3-dev python3-pybind11 python3-pytest      # the Python module and its tests
  python3-venv python3-setuptools python3-wheel     # pip install . (pyproject.toml, setup.py)
  openmpi-bin libopenmpi-dev                        # MPI sweeps (docs/cluster.md)
  clang-format                                      # formatting check (scripts/test.sh)
  clang libclang-rt-dev                             # libFuzzer targets (scripts/fuzz.sh)
  libomp-dev                                        # LLVM OpenMP + Archer for TSan (scripts/tsan.sh)
)
packages+=("$@")

if [[ "${DILATANT_SKIP_DEPS:-0}" == 1 ]]; then
  echo "install-deps: DILATANT_SKIP_DEPS=1, skipping"
  exit 0
fi
if ! command -v dpkg-query >/dev/null; then
  echo "install-deps: dpkg-query not found; this script needs Debian/Ubuntu (apt)" >&2
  exit 1
fi

# A package counts as present only when fully installed ("install ok installed").
missing=()
for p in "${packages[@]}"; do
  if [[ "$(dpkg-query -W -f='${Status}' "$p" 2>/dev/null)" != "install ok installed" ]]; then
    missing+=("$p")
  fi
done
if ((${#missing[@]} == 0)); then
  echo "install-deps: all ${#packages[@]} packages already installed"
  exit 0
fi

if ((EUID == 0)); then
  as_root=()
elif command -v sudo >/dev/null; then
  as_root=(sudo)
else
  echo "install-deps: missing ${missing[*]}; run as root or install sudo" >&2
  exit 1
fi
echo "install-deps: installing ${missing[*]}"
"${as_root[@]}" apt-get update
"${as_root[@]}" env DEBIAN_FRONTEND=noninteractive \
  apt-get install -y --no-install-recommends "${packages[@]}"
