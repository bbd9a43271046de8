#!/usr/bin/env bash
# Does another binary go on from a study's state as the study's own binary does?
# Runs both from one point's final state (its checkpoint.bin, with its resolved
# config.toml) for a short stretch at a given lambda, and compares the two result
# folders file by file (scripts/compare_outputs.py: bytes, summary key by key
# without cost keys and version). Identical time series and checkpoints mean a
# refinement or a resumed ramp may run on the other binary without changing
# the physics (docs/sweeps.md "A study that outlasts the machine").
#   scripts/continuation-check.sh OLD_BINARY NEW_BINARY POINT_DIR LAMBDA STRAIN OUT
# e.g. scripts/continuation-check.sh "$(scripts/pinned-binary.sh b6e137e)" build/dilatant \
#        out/paper/decisive-le-mu0.4/points/005-seed=1_lambda=31.6 46.42 0.3 /tmp/check
# Writes OUT/old, OUT/new and OUT/comparison.txt (its last line the verdict);
# exit status 0 when every file is identical but for summary keys one version
# lacks, 1 when anything else differs (round-off included), 2 on bad use.
set -euo pipefail
if [[ $# -ne 6 ]]; then sed -n '2,15p' "$0" >&2; exit 2; fi
old=$1 new=$2 point=$3 lambda=$4 strain=$5 out=$6
for f in "$point/config.toml" "$point/checkpoint.bin"; do
  [[ -f $f ]] || { echo "continuation-check: $f: no such file (a finished point's folder?)" >&2; exit 2; }
done
for b in "$old" "$new"; do
  [[ -x $b ]] || { echo "continuation-check: $b: not an executable" >&2; exit 2; }
done
mkdir -p "$out"
for side in old new; do
  binary=${!side}
  rm -rf "${out:?}/$side"
  "$binary" run "$point/config.toml" --start-from "$point/checkpoint.bin" \
    --set "fluid.lambda=$lambda" --set "run.strain=$strain" \
    --set "run.transient_strain=$(python3 -c "print($strain / 3)")" \
    --set "run.checkpoint_interval=$strain" --set run.snapshot_interval=0.0 --out "$out/$side" -q
done
status=0
python3 "$(dirname "$0")/compare_outputs.py" "$out/old" "$out/new" >"$out/differences.txt" || status=$?
# A summary key that one version writes and the other does not (a new
# measurement) is no difference in the physics; any other line is.
others=$(grep -v -e '^  summary.json: key .* only in \(old\|new\)$' -e '(shown, not counted)$' -e 'files compared' "$out/differences.txt" || true)
{
  echo "# $("$old" --version) ($old) against $("$new" --version) ($new)"
  echo "# from $point, lambda $lambda, $strain strain"
  cat "$out/differences.txt"
  if [[ $status -eq 0 || -z $others ]]; then
    echo "same physics: every file identical but for summary keys one version lacks"
  else
    echo "different: compare_outputs.py exit status $status"
  fi
} | tee "$out/comparison.txt"
[[ $status -eq 0 || -z $others ]]
