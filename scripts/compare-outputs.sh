#!/usr/bin/env bash
# Proof that a change leaves every result as it was: runs a fixed set of short
# runs with an old and a new build of dilatant and compares their output folders
# file by file (scripts/compare_outputs.py: byte for byte, summary.json key by
# key without the cost keys, config.toml shown but not counted unless
# --strict-config). Keep it for every refactor (docs/architecture.md).
#
#   scripts/compare-outputs.sh [--old-rev REV | --old-bin PATH] [--new-bin PATH]
#                              [--keep DIR] [--strict-config] [--accept-roundoff]
#
#   --old-rev REV   build the old side from git revision REV (default: HEAD, i.e.
#                   the working tree against its last commit)
#   --old-bin PATH  use this old dilatant executable instead of building one
#   --new-bin PATH  use this new executable (default: build the working tree)
#   --keep DIR      put builds and outputs in DIR and keep them (default: a
#                   temporary folder, removed at the end)
#   --strict-config     count differences of the resolved config.toml too
#   --accept-roundoff   accept files that differ only in numbers, each by at most
#                       1e-14 relative (they are still listed, with the largest)
# Exit status: 0 all identical, 1 some output differs, 2 bad usage or build failure.
# The runs take about a minute and a half on 2 cores (old and new side by side), plus the builds.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
root=$PWD

old_rev=HEAD old_bin="" new_bin="" keep="" strict=()
while (($# > 0)); do
  case "$1" in
    --old-rev) old_rev=${2:?--old-rev needs a revision}; shift 2 ;;
    --old-bin) old_bin=${2:?--old-bin needs a path}; shift 2 ;;
    --new-bin) new_bin=${2:?--new-bin needs a path}; shift 2 ;;
    --keep) keep=${2:?--keep needs a folder}; shift 2 ;;
    --strict-config) strict+=(--strict-config); shift ;;
    --accept-roundoff) strict+=(--accept-roundoff); shift ;;
    -h | --help) sed -n '2,22p' "$0"; exit 0 ;;
    *) echo "compare-outputs: unknown argument '$1' (see --help)" >&2; exit 2 ;;
  esac
done

if [[ -n "$keep" ]]; then
  work=$(mkdir -p "$keep" && cd "$keep" && pwd)
else
  work=$(mktemp -d)
  trap 'git -C "$root" worktree remove --force "$work/old-src" 2>/dev/null || true; rm -rf "$work"' EXIT
fi

build() {  # build SOURCE_DIR BUILD_DIR -> the dilatant executable
  cmake -S "$1" -B "$2" -G Ninja -DCMAKE_BUILD_TYPE=Release -DBUILD_TESTING=OFF \
    -DDILATANT_BUILD_BENCHMARKS=OFF >"$2.log" 2>&1 &&
    cmake --build "$2" --parallel "$(nproc)" --target dilatant >>"$2.log" 2>&1 ||
    { echo "compare-outputs: build of $1 failed, see $2.log" >&2; exit 2; }
}
if [[ -z "$old_bin" ]]; then
  rev=$(git rev-parse --verify "$old_rev^{commit}" 2>/dev/null) ||
    { echo "compare-outputs: --old-rev $old_rev is not a revision" >&2; exit 2; }
  git worktree remove --force "$work/old-src" 2>/dev/null || true
  git worktree add --detach "$work/old-src" "$rev" >/dev/null
  echo "building old ($old_rev = ${rev:0:10}) ..."
  build "$work/old-src" "$work/old-build"
  old_bin=$work/old-build/dilatant
fi
if [[ -z "$new_bin" ]]; then
  echo "building new (working tree) ..."
  build "$root" "$work/new-build"
  new_bin=$work/new-build/dilatant
fi
[[ -x "$old_bin" && -x "$new_bin" ]] || { echo "compare-outputs: no executable" >&2; exit 2; }

# The runs: small cells (stribeck, coulomb, thickened, 2 threads, resumed, a
# continued flow curve), the committed configs of the paper's cell over a
# little strain, the wall-free (Lees-Edwards) cell under stress and under rate
# control and resumed, a small sediment (dilatant jam), and the two example
# scenes.
# 10 x 6 x 12 R holds ~120 spheres and 4 slabs (so 2 threads share sweeps).
cell=(--set 'cell.size=[10.0, 6.0, 12.0]' --set run.strain=1.0 --set run.transient_strain=0.3
  --set run.snapshot_interval=0.5 --set run.checkpoint_interval=0.25 --set fluid.lambda=30)
# 8 x 6 x 8 R of examples/lees-edwards.toml: ~50 spheres, a second a run.
lees_edwards=(examples/lees-edwards.toml --set 'cell.size=[8.0, 6.0, 8.0]' --set run.strain=0.5
  --set run.transient_strain=0.2 --set run.snapshot_interval=0.25 --set run.checkpoint_interval=0.25)
sweep_file=$work/continuation.toml
cat >"$sweep_file" <<'TOML'
[cell]
size = [10.0, 6.0, 12.0]
[fluid]
lambda = [10.0, 30.0]
[run]
strain = 0.4
transient_strain = 0.1
snapshot_interval = 0.0
[sweep]
continuation = true
continuation_strain = 0.3
continuation_transient_strain = 0.1
TOML

run_case() {  # run_case NAME SIDE BINARY -> outputs in $work/SIDE/NAME
  local name=$1 side=$2 bin=$3 out=$work/$2/$1
  rm -rf "$out"
  case "$name" in
    cell-stribeck) "$bin" run "${cell[@]}" --out "$out" -q ;;
    cell-coulomb) "$bin" run "${cell[@]}" --set friction.law=coulomb --set friction.mu0=0.3 \
      --out "$out" -q ;;
    cell-thickened) "$bin" run "${cell[@]}" --set friction.mu0=0.3 --set fluid.lambda=100 \
      --out "$out" -q ;;
    cell-threads2) "$bin" run "${cell[@]}" --set solver.threads=2 --out "$out" -q ;;
    cell-resumed)
      "$bin" run "${cell[@]}" --set run.strain=0.5 --out "$out" -q
      "$bin" run "${cell[@]}" --resume --out "$out" -q ;;
    lees-edwards-stress) "$bin" run "${lees_edwards[@]}" --out "$out" -q ;;
    lees-edwards-rate) "$bin" run "${lees_edwards[@]}" --set cell.control=rate \
      --set cell.shear_rate=1e-3 --out "$out" -q ;;
    lees-edwards-resumed)
      "$bin" run "${lees_edwards[@]}" --set run.strain=0.3 --out "$out" -q
      "$bin" run "${lees_edwards[@]}" --resume --out "$out" -q ;;
    sediment) "$bin" jam examples/jamming/sediment.toml --set 'sediment.size=[6.0, 6.0, 14.0]' \
      --set sediment.samples=1 --out "$out" -q ;;
    example-thickened | example-viscous) # the committed configs of the paper's cell
      "$bin" run "examples/cell/${name#example-}.toml" --set run.strain=0.15 \
        --set run.transient_strain=0.05 --set run.snapshot_interval=0.1 --out "$out" -q ;;
    bench-coulomb) "$bin" run bench/configs/coulomb.toml --set run.strain=0.1 \
      --set run.transient_strain=0.05 --set run.snapshot_interval=0 --out "$out" -q ;;
    sweep-continued) "$bin" sweep "$sweep_file" --out "$out" --jobs 1 --no-plots -q ;;
    scene-pile) "$bin" run examples/pile/pile.toml --set run.time=0.3 --out "$out" -q ;;
    scene-incline) "$bin" run examples/incline/incline.toml --set run.time=0.3 --out "$out" -q ;;
  esac
}
cases=(cell-stribeck cell-coulomb cell-thickened cell-threads2 cell-resumed
  lees-edwards-stress lees-edwards-rate lees-edwards-resumed sediment example-thickened example-viscous bench-coulomb sweep-continued scene-pile scene-incline)

status=0
printf '%-22s %s\n' run result
for c in "${cases[@]}"; do
  start=$SECONDS
  run_case "$c" old "$old_bin" 2>"$work/$c.old.err" &
  old_pid=$!
  run_case "$c" new "$new_bin" 2>"$work/$c.new.err" || true
  wait "$old_pid" || true
  result=0
  report=$(python3 scripts/compare_outputs.py "$work/old/$c" "$work/new/$c" "${strict[@]}") ||
    result=$?
  case $result in
    0) verdict=identical
      [[ "$report" == *"in round-off only"* ]] && verdict="identical up to round-off (accepted)" ;;
    3) verdict="ROUND-OFF ONLY (see --accept-roundoff)"; status=1 ;;
    *) verdict=DIFFERENT; status=1 ;;
  esac
  printf '%-22s %s (%s s)\n' "$c" "$verdict" $((SECONDS - start))
  printf '%s\n' "$report"
done
echo "compare-outputs: $([[ $status == 0 ]] && echo "all identical" || echo "outputs differ")"
exit $status
