#!/usr/bin/env bash
# Unconverged steps redone at half the step (solver.redo_unconverged,
# docs/model.md "Unconverged steps"), measured on the dumped step problems of
# bench/dump_problems.sh: each problem solved by build/bench/dilatant-solve-step
# at the default stopping test (load-scaled residual 1e-2, one thread) without
# and with the redo, and per group the steps that converge, the steps that fail
# even at 1/64 of their step, the halvings, and the work (sweep-equivalents,
# the undone attempts' included).
#
#   bash bench/redo_problems.sh [--problems DIR] [--label L] [--groups "A B1 ..."]
#
# Writes bench/results/step-problems/redo-LABEL/GROUP-{false,true}.txt (the
# driver's output) and table.md. A few minutes of one core.
set -uo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.." || exit 1
source bench/lib.sh
parse_problem_args redo_problems.sh "A B1 B2 E G" "$@"
bash scripts/build.sh release dilatant-solve-step >/dev/null || { echo "redo_problems.sh: build failed" >&2; exit 1; }
results="bench/results/step-problems/redo-$label"
mkdir -p "$results"
for g in $groups; do
  for redo in false true; do
    echo "[$(date -u +%H:%M:%S)] $g, redo $redo"
    build/bench/dilatant-solve-step "$problems/$g" --targets 1e-2 --set solver.convergence=residual \
      --set solver.tolerance=1e-2 --set solver.redo_unconverged=$redo >"$results/$g-$redo.txt" 2>&1
  done
done
# shellcheck disable=SC2086  # the groups are words
python3 - "$results" "$(git rev-parse --short HEAD)" $groups <<'PY'
import statistics as st, sys
results, head, *groups = sys.argv[1:]

def parse(path):
    # file passes SE residual typical converged redos SE_to_1e-2, or "file  failed: ..."
    out = []
    for line in open(path).read().splitlines()[1:]:
        f = line.split()
        if "failed:" in line:
            out.append({"failed": True, "why": line.split("failed: ", 1)[1]})
        else:
            out.append({"failed": False, "se": float(f[2]), "conv": f[5] == "true", "redos": int(f[6])})
    return out

lines = [f"# Unconverged steps redone at half the step (commit {head})", "",
         "Each dumped problem solved at the load-scaled residual 1e-2 (one thread), without and with "
         "`solver.redo_unconverged`; SE counts the undone attempts' work too.", "",
         "| group | problems | no redo: converged | no redo: SE (median, max) | redo: converged | "
         "redo: failed at dt/64 | halvings (total) | redo: SE (median, max) |",
         "|---|---|---|---|---|---|---|---|"]
failures = []
for g in groups:
    a, b = parse(f"{results}/{g}-false.txt"), parse(f"{results}/{g}-true.txt")
    sa = [x["se"] for x in a]
    sb = [x["se"] for x in b if not x["failed"]]
    lines.append(f"| {g} | {len(a)} | {sum(x['conv'] for x in a)} | {st.median(sa):.0f}, {max(sa):.0f} | "
                 f"{sum((not x['failed']) and x['conv'] for x in b)} | {sum(x['failed'] for x in b)} | "
                 f"{sum(x.get('redos', 0) for x in b)} | {st.median(sb):.0f}, {max(sb):.0f} |")
    failures += [f"- {g}: {x['why']}" for x in b if x["failed"]]
lines += ["", "Steps that failed even at 1/64 of their step:", ""] + (failures or ["- none"])
open(f"{results}/table.md", "w").write("\n".join(lines) + "\n")
print("\n".join(lines))
PY
