#!/usr/bin/env bash
# The dumped step problems of bench/dump_problems.sh solved again
# (build/bench/dilatant-solve-step, one group at a time, one thread) under the
# runs' own solver settings and under plain Gauss-Seidel (relaxation 1, no
# skipping of open contacts), with the work in sweep-equivalents (SE) at which
# the contact residual (solver/contact_residual.hpp, as of the commit named in
# the table) first reaches 1e-2 and 1e-3; per group the medians.
#
#   bash bench/solve_problems.sh [--problems DIR] [--label L] [--groups "A B1 ..."]
#
# Reads DIR/GROUP/ (default bench/problems) and DIR/MANIFEST.csv; writes
# bench/results/step-problems/groups-LABEL/ (LABEL: today's date):
#   solve-SETTING.csv                   one row per problem: passes, SE and
#                                       residual at the end, SE to each target
#                                       (empty: never reached in the solve)
#   groups.md                           the dumps per group and the medians
# and every pass's residual to DIR/solves/LABEL/GROUP-SETTING.csv (not committed).
# A few minutes of one core for the whole set.
set -uo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.." || exit 1
source bench/lib.sh
parse_problem_args solve_problems.sh "" "$@"
if [[ -z "$groups" ]]; then
  for d in "$problems"/*/index.csv; do groups+=" $(basename "$(dirname "$d")")"; done
fi
bash scripts/build.sh release dilatant-solve-step >/dev/null || { echo "solve_problems.sh: build failed" >&2; exit 1; }
results="bench/results/step-problems/groups-$label"
passes="$problems/solves/$label"
mkdir -p "$results" "$passes"

settings=(run plain-gs sor gs)
# run / plain-gs: stop as the dumped run did (its config.toml, written before
# solver.convergence, keeps the relative change at 1e-4); sor / gs: the same
# two methods run on until the load-scaled residual is 1e-3 (or the cap), the
# M0 baseline of docs/contact-solve-plan.md: the work today's sweeps need.
declare -A overrides=(
  [run]=""
  [plain-gs]="--set solver.relaxation=1.0 --set solver.skip_open_contacts=false"
  [sor]="--set solver.convergence=residual --set solver.tolerance=1e-3"
  [gs]="--set solver.convergence=residual --set solver.tolerance=1e-3 --set solver.relaxation=1.0 --set solver.skip_open_contacts=false")
for s in "${settings[@]}"; do
  table="$results/solve-$s.csv"
  echo "group,file,passes,sweep_equivalents,residual_max,typical_impulse,converged,redos,se_to_1e-2,se_to_1e-3" >"$table"
  for g in $groups; do
    [[ $(wc -l <"$problems/$g/index.csv") -gt 1 ]] || continue
    echo "[$(date -u +%H:%M:%S)] $g, $s"
    # shellcheck disable=SC2086  # the overrides are words
    if ! build/bench/dilatant-solve-step "$problems/$g" ${overrides[$s]} --targets 1e-2,1e-3 \
      --csv "$passes/$g-$s.csv" >"$passes/$g-$s.txt" 2>"$passes/$g-$s.err"; then
      echo "  failed: $(tail -n 1 "$passes/$g-$s.err")"
      continue
    fi
    # file passes SE residual typical_impulse converged redos SE_to_1e-2 SE_to_1e-3 ("-": never)
    tail -n +2 "$passes/$g-$s.txt" | grep -v "  failed: " |
      awk -v g="$g" '{ for (i = 8; i <= 9; i++) if ($i == "-") $i = "";
        print g "," $1 "," $2 "," $3 "," $4 "," $5 "," $6 "," $7 "," $8 "," $9 }' >>"$table"
  done
done

residual_commit=$(git log -1 --format=%h -- src/solver/contact_residual.hpp src/solver/contact_residual.cpp bench/tools/solve_step.cpp)
python3 - "$problems/MANIFEST.csv" "$results" "$(git rev-parse --short HEAD)" "$residual_commit" "${settings[@]}" <<'PY'
import csv, json, math, os, statistics, sys
from collections import defaultdict

manifest, results, head, residual_commit, *settings = sys.argv[1:]
rows = [r for r in csv.DictReader(open(manifest))]
order = list(dict.fromkeys(r["group"] for r in rows))
by_group = defaultdict(list)
for r in rows:
    if r["file"]:
        by_group[r["group"]].append(r)
status = {r["group"]: (r["run_status"], r["run_seconds"], r["commit"]) for r in rows}

def fmt(x, spec=".0f"):
    return "—" if x is None else ("> cap" if math.isinf(x) else format(x, spec))

out = [f"# Dumped step problems per group ({results.split('groups-')[-1]})", "",
       "Dumped by `bash bench/dump_problems.sh` (commit "
       f"{', '.join(sorted({c for _, _, c in status.values()}))}, one thread); solved again by "
       "`bash bench/solve_problems.sh` (HEAD " + head + "; residual: "
       "solver/contact_residual.hpp as of commit " + residual_commit + ", relative to the RMS "
       "loaded impulse, not the load-scaled residual of issue 30 item 1).", "",
       "## The dumps", "",
       "| group | problems (regular + unconverged) | strain | passes (min–median–max) | at the pass cap | "
       "residual max (median, max) | file size | run | run time |",
       "|---|---|---|---|---|---|---|---|---|"]
for g in order:
    ps = by_group[g]
    st, sec, _ = status[g]
    if not ps:
        out.append(f"| {g} | 0 | — | — | — | — | — | {st} | {sec} s |")
        continue
    reg = sum(p["reason"] == "regular" for p in ps)
    strains = [float(p["strain"]) for p in ps]
    passes = [int(p["passes"]) for p in ps]
    capped = sum(p["converged"] == "false" for p in ps)
    res = [float(p["contact_residual_max"]) for p in ps]
    size = [int(p["bytes"]) / 1024 for p in ps]
    out.append(f"| {g} | {len(ps)} ({reg} + {len(ps) - reg}) | {min(strains):.3f}–{max(strains):.3f} | "
               f"{min(passes)}–{statistics.median(passes):.0f}–{max(passes)} | {capped} | "
               f"{statistics.median(res):.2g}, {max(res):.2g} | "
               f"{statistics.median(size):.0f} KB each, {sum(size) / 1024:.1f} MB | {st} | {sec} s |")

out += ["", "The runs themselves (their summary.json): steps, steps that ended at the pass cap, "
        "mean passes and sweep-equivalents per step, the inertial number, the worst contact "
        "residual of any step.", "",
        "| group | steps | at the cap | passes / step | SE / step | I | residual max | jammed |",
        "|---|---|---|---|---|---|---|---|"]
for g in order:
    path = os.path.join(os.path.dirname(manifest), g, "summary.json")
    if not os.path.isfile(path):
        out.append(f"| {g} | — | — | — | — | — | — | — |")
        continue
    j = json.load(open(path))
    out.append(f"| {g} | {j['steps']} | {j['frac_steps_unconverged']:.1%} | "
               f"{j['mean_iterations']:.0f} | {j['sweep_equivalents_per_step']:.0f} | "
               f"{j['inertial_number']:.2g} | {j['contact_residual_max']:.2g} | {j['jammed']} |")

solved = {}
for s in settings:
    solved[s] = defaultdict(list)
    for r in csv.DictReader(open(f"{results}/solve-{s}.csv")):
        solved[s][r["group"]].append(r)

def median_to(rs, key):
    v = [float(r[key]) if r[key] else math.inf for r in rs]
    return (statistics.median(v) if v else None), sum(not math.isinf(x) for x in v), len(v)

out += ["", "## Solved again: median sweep-equivalents to residual 1e-2 and 1e-3", "",
        "`run`: each run's own solver settings (relaxation 1.3, skipping open contacts, "
        "tolerance 1e-4 on the change-based stop, 1000 passes); `plain-gs`: "
        "`--set solver.relaxation=1.0 --set solver.skip_open_contacts=false`; `sor` and `gs`: "
        "the same two run on to the load-scaled residual 1e-3 "
        "(`--set solver.convergence=residual --set solver.tolerance=1e-3`), the M0 baseline. "
        "A problem whose solve stopped (converged by the change-based test, or at the cap) "
        "before reaching a target counts as never (> cap); (k/n): problems that reached it.", "",
        "| group | problems | " + " | ".join(
            f"{s}: SE to 1e-2 | {s}: SE to 1e-3 | {s}: SE to its end" for s in settings) + " |",
        "|---|---|" + "---|---|---|" * len(settings)]
for g in order:
    if not by_group[g]:
        continue
    cells = []
    for s in settings:
        rs = solved[s][g]
        for key in ("se_to_1e-2", "se_to_1e-3"):
            m, k, n = median_to(rs, key)
            cells.append(f"{fmt(m)} ({k}/{n})")
        ends = [float(r["sweep_equivalents"]) for r in rs]
        cells.append(fmt(statistics.median(ends)) if ends else "—")
    out.append(f"| {g} | {len(by_group[g])} | " + " | ".join(cells) + " |")
if "run" in solved:
    ran = {(r["group"], r["file"].split("/")[-1]): r["passes"] for r in rows if r["file"]}
    same = [ran.get((r["group"], r["file"])) == r["passes"]
            for rs in solved["run"].values() for r in rs]
    out += ["", f"Replay under `run`: {sum(same)} of {len(same)} problems end with the run's own "
            "pass count (index.csv), as an exact replay must."]
open(f"{results}/groups.md", "w").write("\n".join(out) + "\n")
print("\n".join(out))
PY
