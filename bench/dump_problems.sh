#!/usr/bin/env bash
# The benchmark set of dumped contact-step problems (issue 30, item 2;
# docs/contact-solve-plan.md, "2. Step problems on disk", the table of groups
# A-G): one `dilatant run ... --dump-steps` a group, at one thread, whose dumps
# (checkpoints of the state each chosen step starts from, with the run's
# config.toml and index.csv; drivers/step_dumps.hpp) go to OUT/GROUP/.
# `build/bench/dilatant-solve-step OUT/GROUP` solves them again under any
# solver settings (bench/solve_problems.sh: the per-group medians).
#
#   bash bench/dump_problems.sh [--groups "A B1 ..."] [--out DIR] [--force]
#                               [--scratch DIR] [--timeout SECONDS] [--dry-run]
#
#   --groups   the groups to dump (default: all, A B1 B2 C D E F1 F2 G)
#   --out      where the dump folders go (default bench/problems, gitignored but
#              for its MANIFEST.csv)
#   --force    dump a group again even if OUT/GROUP/index.csv exists (otherwise
#              it is skipped: the script resumes where a stopped one left off)
#   --scratch  the runs' own output folders (default /tmp/dump-problems-runs)
#   --timeout  stop a group's run after this long (default 3600 s); it is sent
#              SIGTERM, writes a checkpoint and exits 1: its dumps so far stay
#   --dry-run  print the commands, run nothing
#
# Cost: about 20 minutes of one core for all groups (measured 2026-11-27 at
# 7d9ca72: A 2, B1 4, B2 4.5, C 1, D 3.5, E 1, F1+F2 1, G 4 minutes).
#
# Each group is dumped into OUT/GROUP.partial and renamed to OUT/GROUP when its
# run has ended, so OUT/GROUP/index.csv exists only for a finished group. A run
# that fails or blows up (non-zero exit, a timeout) does not stop the others:
# its status is recorded in OUT/GROUP/run-info.txt, the log and the manifest,
# and the steps it dumped before it stopped are kept. Beside the dumps each
# group keeps run-info.txt (command, commit, status, seconds), run.log (the
# run's stderr) and summary.json (the run's, if it wrote one).
#
# Then OUT/MANIFEST.csv: one row per dumped step (group, file relative to OUT,
# config, overrides, dump options, commit, step, strain, sha256, then the
# columns of the group's index.csv: reason, converged, passes,
# sweep_equivalents, contacts, residual_change, contact_residual_max; and the
# run's status and seconds); a group that dumped nothing gets one row with an
# empty file. It is copied to bench/problems/MANIFEST.csv (committed) when OUT
# is elsewhere. The sha256 shows whether a regeneration is identical (same
# binary, same bits; the paths of a near-jamming run are chaotic across builds).
#
# Changes against the plan's table (checked against the configs and the CLI of
# commit 7d9ca72):
#   --dump-problems is --dump-steps (the dumps are checkpoints, not DILSTEP files);
#   C and G run the built-in cell with overrides: examples/paper/dense-window.toml
#     and newtonian-phi.toml are sweep files (lists, a [sweep] table) that
#     `dilatant run` refuses; the built-in cell has their stribeck law (mu0 0.1,
#     s_c 5e-5, s_lim 0.1), seed 1 and tolerance 1e-4;
#   G: run.transient_strain=1.0 added (the built-in 6 must be < run.strain = 2),
#     and 2 regular dumps past strain 1.5 besides the unconverged ones, so that
#     the group is not empty if no step ends at the pass cap;
#   C: --dump-every 28, not 60, and D: 75, not 150: this build takes ~2,300 and
#     ~2,900 steps per strain there, so the plan's spacing gave 4 of C's 8 and
#     4 of D's 6 regular dumps;
#   F is F1 (phi 0.628) and F2 (phi 0.633), two runs.
# --dump-unconverged takes the first K steps that end at the pass cap from the
# start of the run (--dump-from-strain is for regular dumps only), so in B1, B2,
# D and F they are cold-start or transient steps.
set -uo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.." || exit 1

all_groups="A B1 B2 C D E F1 F2 G"
groups=$all_groups out=bench/problems force=0 scratch=/tmp/dump-problems-runs
timeout_s=3600 dry_run=0
usage() {
  echo "usage: dump_problems.sh [--groups \"A B1 ...\"] [--out DIR] [--force]" \
    "[--scratch DIR] [--timeout SECONDS] [--dry-run]" >&2
  exit 2
}
while (($#)); do
  case "$1" in
    --groups) groups=$2; shift 2 ;;
    --out) out=$2; shift 2 ;;
    --force) force=1; shift ;;
    --scratch) scratch=$2; shift 2 ;;
    --timeout) timeout_s=$2; shift 2 ;;
    --dry-run) dry_run=1; shift ;;
    *) usage ;;
  esac
done

# The table: config ("" = the built-in cell), --set overrides, dump options.
declare -A config sets dumps
config[A]=bench/configs/coulomb.toml
sets[A]="run.strain=1.0"
dumps[A]="--dump-from-strain 0.4 --dump-every 130 --dump-max 10"

config[B1]=bench/configs/coulomb-dense.toml
sets[B1]="cell.phi=0.597 run.strain=0.7"
dumps[B1]="--dump-from-strain 0.3 --dump-every 200 --dump-max 6 --dump-unconverged 2"

config[B2]=bench/configs/coulomb-dense.toml
sets[B2]="run.strain=0.6"
dumps[B2]="--dump-from-strain 0.2 --dump-every 300 --dump-max 6 --dump-unconverged 4"

config[C]=""
sets[C]="cell.size=[15.0,10.0,18.0] cell.phi=0.62 fluid.lambda=0.3 run.strain=0.25 run.transient_strain=0.1"
dumps[C]="--dump-from-strain 0.15 --dump-every 28 --dump-max 8"

config[D]=""
sets[D]="cell.phi=0.62 fluid.lambda=1.0 run.strain=0.35 run.transient_strain=0.1"
dumps[D]="--dump-from-strain 0.2 --dump-every 75 --dump-max 6 --dump-unconverged 2"

config[E]=""
sets[E]="run.strain=1.5 run.transient_strain=0.5"
dumps[E]="--dump-unconverged 6 --dump-every 1000 --dump-max 2"

le="cell.size=[12.0,12.0,12.0] cell.control=rate cell.shear_rate=1e-3 friction.law=coulomb friction.mu0=0.0"
config[F1]=examples/lees-edwards.toml
sets[F1]="$le cell.phi=0.628 run.strain=0.3 run.transient_strain=0.1"
dumps[F1]="--dump-from-strain 0.15 --dump-max 2 --dump-every 100 --dump-unconverged 1"
config[F2]=examples/lees-edwards.toml
sets[F2]="$le cell.phi=0.633 run.strain=0.3 run.transient_strain=0.1"
dumps[F2]=${dumps[F1]}

config[G]=""
sets[G]="cell.size=[15.0,10.0,18.0] cell.phi=0.61 fluid.lambda=1.0 fluid.lubrication=normal fluid.drag=stokes run.strain=2.0 run.transient_strain=1.0"
dumps[G]="--dump-unconverged 4 --dump-from-strain 1.5 --dump-every 500 --dump-max 2"

for g in $groups; do
  [[ -v "sets[$g]" ]] || { echo "dump_problems.sh: no group '$g' (groups: $all_groups)" >&2; exit 2; }
done

log() { echo "[$(date -u +%H:%M:%S)] $*"; }

if ((!dry_run)); then
  bash scripts/build.sh release dilatant >/dev/null || { echo "dump_problems.sh: build failed" >&2; exit 1; }
fi
commit=$(git rev-parse --short HEAD)
# Sources changed against HEAD make the dumps no longer HEAD's.
git diff --quiet HEAD -- src CMakeLists.txt cmake 2>/dev/null || commit="$commit-dirty"
mkdir -p "$out" "$scratch"

for g in $groups; do
  dest="$out/$g"
  if [[ -f "$dest/index.csv" ]] && ((!force)); then
    log "$g: $dest/index.csv exists, skipped (--force dumps it again)"
    continue
  fi
  args=()
  [[ -n "${config[$g]}" ]] && args+=("${config[$g]}")
  for s in ${sets[$g]} solver.threads=1; do args+=(--set "$s"); done
  # shellcheck disable=SC2206  # the dump options are words
  dump_args=(${dumps[$g]})
  cmd=(build/dilatant run "${args[@]}" --quiet --out "$scratch/$g" --dump-steps "$dest.partial"
    "${dump_args[@]}")
  if ((dry_run)); then
    echo "$g: ${cmd[*]}"
    continue
  fi
  rm -rf "$dest.partial" "${scratch:?}/$g"
  log "$g: ${cmd[*]}"
  start=$(date +%s)
  # --foreground: the run gets the SIGTERM itself and stops cleanly.
  timeout --foreground -s TERM "$timeout_s" "${cmd[@]}" 2>"$scratch/$g.stderr"
  rc=$?
  seconds=$(($(date +%s) - start))
  case $rc in
    0) status=ok ;;
    124) status="timeout after ${timeout_s} s" ;;
    *) status="exit $rc" ;;
  esac
  if [[ ! -d "$dest.partial" ]]; then
    # The run stopped before the dumper made its folder (a refused config).
    mkdir -p "$dest.partial"
    echo "file,step,strain,reason,converged,passes,sweep_equivalents,contacts,residual_change,contact_residual_max" \
      >"$dest.partial/index.csv"
  fi
  cp "$scratch/$g.stderr" "$dest.partial/run.log"
  [[ -f "$scratch/$g/summary.json" ]] && cp "$scratch/$g/summary.json" "$dest.partial/summary.json"
  {
    echo "group=$g"
    echo "config=${config[$g]:-<built-in>}"
    echo "overrides=${sets[$g]} solver.threads=1"
    echo "dump_options=${dumps[$g]}"
    echo "commit=$commit"
    echo "status=$status"
    echo "seconds=$seconds"
    echo "finished=$(date -u +%Y-%m-%dT%H:%MZ)"
    echo "command=${cmd[*]}"
  } >"$dest.partial/run-info.txt"
  rm -rf "$dest"
  mv "$dest.partial" "$dest"
  n=$(($(wc -l <"$dest/index.csv") - 1))
  log "$g: $status, $seconds s, $n steps dumped$( ((rc)) && echo "; stderr: $(tail -n 2 "$dest/run.log" | tr '\n' ' ')")"
done
((dry_run)) && exit 0

# The manifest, over every group folder in OUT (dumped now or before).
python3 - "$out" "$all_groups" <<'PY'
import csv, hashlib, os, sys

out, order = sys.argv[1], sys.argv[2].split()
groups = [g for g in order if os.path.isfile(os.path.join(out, g, "index.csv"))]
index_cols = ["reason", "converged", "passes", "sweep_equivalents", "contacts",
              "residual_change", "contact_residual_max"]
head = ["group", "file", "config", "overrides", "dump_options", "commit", "step", "strain",
        "sha256", "bytes"] + index_cols + ["run_status", "run_seconds"]
rows = []
for g in groups:
    info = {}
    info_path = os.path.join(out, g, "run-info.txt")
    if os.path.isfile(info_path):
        for line in open(info_path):
            k, _, v = line.rstrip("\n").partition("=")
            info[k] = v
    base = {"group": g, "config": info.get("config", ""), "overrides": info.get("overrides", ""),
            "dump_options": info.get("dump_options", ""), "commit": info.get("commit", ""),
            "run_status": info.get("status", ""), "run_seconds": info.get("seconds", "")}
    index = list(csv.DictReader(open(os.path.join(out, g, "index.csv"))))
    if not index:
        rows.append(dict(base))
    for r in index:
        path = os.path.join(out, g, r["file"])
        row = dict(base, file=f"{g}/{r['file']}", step=r["step"], strain=r["strain"])
        if os.path.isfile(path):
            data = open(path, "rb").read()
            row.update(sha256=hashlib.sha256(data).hexdigest(), bytes=len(data))
        row.update({k: r.get(k, "") for k in index_cols})
        rows.append(row)
with open(os.path.join(out, "MANIFEST.csv"), "w", newline="") as f:
    w = csv.DictWriter(f, fieldnames=head, lineterminator="\n")
    w.writeheader()
    w.writerows(rows)
print(f"{os.path.join(out, 'MANIFEST.csv')}: {sum(1 for r in rows if r.get('file'))} steps "
      f"in {len(groups)} groups")
PY
if [[ "$(realpath "$out")" != "$(realpath -m bench/problems)" ]]; then
  mkdir -p bench/problems
  cp "$out/MANIFEST.csv" bench/problems/MANIFEST.csv
fi
