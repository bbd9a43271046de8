#!/usr/bin/env bash
# A stress ramp (continuation) that starts from a saved state instead of a
# cold start: each lambda runs from the previous point's final checkpoint.
# Resumable: a point whose summary.json exists is kept; the ramp stops at its
# first jam.
#   scripts/ramp_from_state.sh CONFIG START_CHECKPOINT OUT [--set KEY=VALUE]... LAMBDA...
#   (DILATANT=path/to/dilatant, default build/dilatant)
set -euo pipefail
config=$1 start=$2 out=$3
shift 3
sets=()
while [[ $# -gt 0 && $1 == --set ]]; do
  sets+=(--set "$2")
  shift 2
done
dilatant=${DILATANT:-build/dilatant}
previous=$start
mkdir -p "$out"
for lambda in "$@"; do
  point="$out/lambda=$lambda"
  if [[ ! -f "$point/summary.json" ]]; then
    resume=()
    [[ -f "$point/checkpoint.bin" ]] && resume=(--resume)
    if ((${#resume[@]} == 0)); then
      "$dilatant" run "$config" --start-from "$previous" "${sets[@]}" --set "fluid.lambda=$lambda" \
        --out "$point" -q
    else
      "$dilatant" run "$config" "${sets[@]}" --set "fluid.lambda=$lambda" --out "$point" \
        --resume -q
    fi
  fi
  if grep -q '"jammed": true' "$point/summary.json"; then
    echo "ramp_from_state: jammed at lambda $lambda; stopping" >&2
    break
  fi
  previous="$point/checkpoint.bin"
done
