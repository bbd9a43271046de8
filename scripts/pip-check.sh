#!/usr/bin/env bash
# What a Python user does (docs/python.md "Install with pip"), checked in CI:
# a fresh venv over Debian's Python (numpy, matplotlib and pytest from apt,
# hence --system-site-packages), `pip install` of this source tree (setup.py
# drives CMake), then the binding tests against the installed package and its
# `dilatant` command, run from outside the source tree, with no PYTHONPATH.
#   scripts/pip-check.sh [VENV]   (default: build-pip/venv; the build stays in build-pip/)
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
source_dir=$PWD
venv=${1:-build-pip/venv}
rm -rf "$venv"
/usr/bin/python3 -m venv --system-site-packages "$venv"
venv=$(cd "$venv" && pwd)
# --no-build-isolation: setuptools and wheel from Debian (no network);
# --no-index: numpy and matplotlib are already there, nothing is downloaded.
# Installed from a copy of the tree that is deleted before the tests: the
# installed package must not lean on the source tree (its plot scripts).
copy=$(mktemp -d)
trap 'rm -rf "$copy"' EXIT
tar -C "$source_dir" --exclude='./build*' --exclude=./.git --exclude=./out --exclude=./runs -cf - . | tar -C "$copy" -xf -
"$venv/bin/python" -m pip install --no-build-isolation --no-index "$copy"
rm -rf "$copy"
unset PYTHONPATH
export PATH="$venv/bin:$PATH"  # as `. venv/bin/activate` does
cd "$venv"
"$venv/bin/python" - <<'PY'
import shutil, sys
import dilatant
where = dilatant.__file__
assert where.startswith(sys.prefix), f"dilatant imported from {where}, not from the venv {sys.prefix}"
command = shutil.which("dilatant")
assert command and command.startswith(sys.prefix), f"`dilatant` on PATH is {command}"
print(f"pip-check: dilatant {dilatant.__version__} from {where}, command {command}")
PY
dilatant --version
MPLBACKEND=Agg PYTHONDONTWRITEBYTECODE=1 \
  "$venv/bin/python" -m pytest -q -p no:cacheprovider "$source_dir/python/tests"
