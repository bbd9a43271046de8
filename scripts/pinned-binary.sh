#!/usr/bin/env bash
# Builds the `dilatant` of an earlier commit, for a study that must finish with
# the binary it started with (its points' summaries name that version; mixing
# versions within one table would mix whatever changed between them).
#
#   scripts/pinned-binary.sh COMMIT     prints the binary's path on stdout
#
# The commit is checked out into build-pinned/COMMIT/src (a git worktree) and
# built by that commit's own scripts/build.sh (release, its target `dilatant`:
# the compiler options it was built with then), so the binary computes what
# the study's earlier points computed, bit for bit on the same kind of machine.
# A second call finds it built and only prints the path. Minutes on 2 cores;
# needs scripts/install-deps.sh's packages.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
if (($# != 1)); then
  echo "usage: scripts/pinned-binary.sh COMMIT" >&2
  exit 2
fi
if ! commit=$(git rev-parse --verify --quiet "$1^{commit}"); then
  echo "pinned-binary: $1: not a commit of this repository" >&2
  exit 2
fi
short=${commit:0:7}
root=$PWD/build-pinned/$short
binary=$root/src/build/dilatant
if [[ ! -x $binary ]]; then
  if [[ ! -d $root/src ]]; then
    git worktree prune
    git worktree add --detach "$root/src" "$commit" >&2
  fi
  bash "$root/src/scripts/build.sh" release dilatant >&2
fi
echo "$binary"
