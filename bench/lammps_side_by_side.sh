#!/usr/bin/env bash
# Side by side with the LAMMPS anchor at matched inertial number (issue 12,
# item 5): wall time per unit strain of Debian's LAMMPS (soft frictional
# spheres, ../shared/anchors/lammps) and of dilatant (hard spheres, Contact
# Dynamics) on the paper's cell (25 x 10 x 27 R), Coulomb friction 0.3, at two
# points, run back to back, one process at a time (1 MPI rank, 1 thread):
#
#   hi: I_R ~ 0.04   bench/configs/coulomb.toml        (phi 0.59)
#   lo: I_R < 0.005  bench/configs/coulomb-dense.toml  (phi 0.598)
#
#   bash bench/lammps_side_by_side.sh [--label L] [--binary PATH] [--points "hi lo"]
#                                     [--lammps-from LABEL0] [--report-only]
#                                     [-- --set solver.step_frame=flow ...]
#
# Settings after -- are passed to both of our invocations (the table's
# config.toml records them).
# --report-only prints the table of an earlier run of LABEL without running anything.
# --lammps-from reuses the LAMMPS summaries of the earlier run LABEL0 (same
# machine, same session) and runs only dilatant: for a new build of ours; the
# table then says so.
# I_R = gdot R sqrt(rho/P) with R the largest radius (dilatant's
# inertial_number). Ours is stress-controlled at constant volume, so its I_R
# follows from phi; it runs first, and the anchor (pressure-controlled, rate
# imposed) is then run at I = 1.8 x our measured I_R: the anchor's I is based
# on the mean diameter <d> = 1.8 R. Its measured I lands within a few % of the
# target (its gap and pressure float); both measured I_R are in the table.
#
# Ours runs in two invocations: WARM strain from the cold start (a linear
# velocity profile), then END - WARM strain more, continued from the first's
# final state (`--start-from` its checkpoint, into a second folder; a finished
# run's run.strain cannot be raised on `--resume`). The second invocation's
# summary.json and timeseries.csv are the steady state's alone: its cost
# (wall_time_per_strain_s, steps_per_strain, ns_per_contact_update) and the
# sweeps per step of its rows.
# LAMMPS' cost is its timed run of 0.5 strain after 1.5 + 0.2 strain of
# preparation (the anchor's own split).
#
# Keeps every summary under bench/results/lammps-side-by-side/LABEL/ (with the
# load average around each run in load.txt) and prints the table. The wall
# times are the result: run it on a quiet machine. No timing is asserted.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

label=$(date +%Y%m%d)
binary=""
points="hi lo"
report_only=0
lammps_from=""
extra=()
while (($#)); do
  case "$1" in
    --) shift; extra=("$@"); break ;;
    --lammps-from) lammps_from=$2; shift 2 ;;
    --label) label=$2; shift 2 ;;
    --binary) binary=$2; shift 2 ;;
    --points) points=$2; shift 2 ;;
    --report-only) report_only=1; shift ;;
    *) echo "usage: lammps_side_by_side.sh [--label L] [--binary PATH] [--points \"hi lo\"] [--lammps-from L0] [--report-only] [-- --set KEY=VALUE ...]" >&2
       exit 2 ;;
  esac
done
results="bench/results/lammps-side-by-side/$label"
if ((report_only == 0)); then
  anchor="${LAMMPS_ANCHOR:-$(cd .. && pwd)/shared/anchors/lammps}"
  [[ -f "$anchor/run.sh" ]] || { echo "lammps_side_by_side.sh: no $anchor/run.sh (set LAMMPS_ANCHOR)" >&2; exit 2; }
  bash scripts/install-deps.sh lammps
  if [[ -z "$binary" ]]; then
    bash scripts/build.sh release dilatant
    binary=build/dilatant
  fi

  # point -> our config, WARM and END strain (LAMMPS is aimed at our measured I_R)
  declare -A config=([hi]=bench/configs/coulomb.toml [lo]=bench/configs/coulomb-dense.toml)
  declare -A warm=([hi]=0.4 [lo]=0.3)
  declare -A end=([hi]=1.0 [lo]=0.7)

  mkdir -p "$results"
  scratch=$(mktemp -d)
  trap 'rm -rf "$scratch"' EXIT
  load() { uptime | sed 's/.*load average: //'; }
  # cpu_time FILE COMMAND...: runs COMMAND, writes its CPU seconds (user + system) to FILE.
  cpu_time() {
    python3 -c 'import resource, subprocess, sys
rc = subprocess.run(sys.argv[2:]).returncode
u = resource.getrusage(resource.RUSAGE_CHILDREN)
open(sys.argv[1], "w").write("%.2f\n" % (u.ru_utime + u.ru_stime))
sys.exit(rc)' "$@"
  }
  note() { echo "$*" | tee -a "$results/load.txt"; }
  : > "$results/load.txt"

  for point in $points; do
    warm_out="$scratch/dilatant-$point-warm" out="$scratch/dilatant-$point"
    common=(--quiet --set solver.threads=1 "${extra[@]}")
    note "=== $point dilatant ${config[$point]} 0 -> ${warm[$point]} strain $(date -u +%H:%M:%SZ) load before: $(load)"
    "$binary" run "${config[$point]}" "${common[@]}" --out "$warm_out" \
      --set "run.strain=${warm[$point]}" \
      --set "run.transient_strain=$(python3 -c "print(${warm[$point]} / 2)")"
    cp "$warm_out/summary.json" "$results/$point-dilatant-warm.json"
    note "=== $point dilatant ${warm[$point]} -> ${end[$point]} strain (--start-from the warm-up) $(date -u +%H:%M:%SZ) load before: $(load)"
    cpu_time "$results/$point-dilatant-cpu-s.txt" \
      "$binary" run "${config[$point]}" "${common[@]}" --out "$out" \
      --start-from "$warm_out/checkpoint.bin" \
      --set "run.strain=$(python3 -c "print(${end[$point]} - ${warm[$point]})")" \
      --set run.transient_strain=0
    echo "continued from the warm-up" >"$results/$point-dilatant-start.txt"
    note "    load after: $(load)"
    cp "$out/summary.json" "$results/$point-dilatant.json"
    cp "$out/config.toml" "$results/$point-dilatant.toml"
    cp "$out/timeseries.csv" "$results/$point-dilatant-timeseries.csv"

    if python3 -c "import json, sys; sys.exit(not json.load(open('$results/$point-dilatant.json'))['jammed'])"; then
      note "    $point: dilatant reports jammed: true; no inertial number to match, LAMMPS skipped"
      continue
    fi
    if [[ -n "$lammps_from" ]]; then
      cp "bench/results/lammps-side-by-side/$lammps_from/$point-lammps.json" "$results/$point-lammps.json"
      note "    $point: LAMMPS not rerun; its summary is that of the run labelled $lammps_from"
      continue
    fi
    # The anchor's I is on <d> = 1.8 R: aim it at our measured I_R.
    lammps_I=$(python3 -c "import json; print('%.4g' % (1.8 * json.load(open('$results/$point-dilatant.json'))['inertial_number']))")
    note "=== $point lammps I=$lammps_I $(date -u +%H:%M:%SZ) load before: $(load)"
    NP_LIST=1 I="$lammps_I" OUT="$scratch/lammps-$point" bash "$anchor/run.sh" | tail -n 1
    note "    load after: $(load)"
    cp "$scratch/lammps-$point/summary.json" "$results/$point-lammps.json"
  done
  {
    echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs)"
    echo "lammps: $(dpkg-query -W -f='${Version}' lammps)"
    echo "commit: $(git rev-parse --short HEAD) (binary: $binary)"
    echo "date: $(date -u +%Y-%m-%dT%H:%MZ)"
  } > "$results/machine.txt"
fi

/usr/bin/env python3 - "$results" <<'PY'
import csv, json, pathlib, sys
folder = pathlib.Path(sys.argv[1])
print(f"\n#### {folder.name}\n")
print("| point | code | I_R | phi_bulk | steps / strain | sweeps / step | sweep-equivalents / step | "
      "steps at the cap | contacts | ns / contact update | wall s / strain | CPU s / strain | "
      "LAMMPS / dilatant (wall) |")
print("|---|---|---|---|---|---|---|---|---|---|---|---|---|")
for point in ("hi", "lo"):
    f_l, f_d = folder / f"{point}-lammps.json", folder / f"{point}-dilatant.json"
    if f_d.exists() and json.loads(f_d.read_text())["jammed"]:
        print(f"| {point} | dilatant reports jammed: true (no LAMMPS run) |" + " |" * 11)
        continue
    if not (f_l.exists() and f_d.exists()):
        continue
    lam, ours = json.loads(f_l.read_text())["1"], json.loads(f_d.read_text())
    warm = json.loads((folder / f"{point}-dilatant-warm.json").read_text())["strain"]
    # The steady run continued from the warm-up (POINT-dilatant-start.txt says
    # so): its strain starts at 0, and its rows are all steady. Runs labelled
    # before 2026-11-27 resumed instead and counted strain from the cold start:
    # their rows past the warm-up.
    continued = (folder / f"{point}-dilatant-start.txt").exists()
    start = 0.0 if continued else warm
    rows = [r for r in csv.DictReader(open(folder / f"{point}-dilatant-timeseries.csv"))
            if float(r["strain"]) > start + 1e-6]
    steps = sum(float(r["steps"]) for r in rows)
    sweeps = sum(float(r["iterations"]) * float(r["steps"]) for r in rows) / steps
    contacts = sum(float(r["contacts"]) * float(r["steps"]) for r in rows) / steps
    capped = sum(float(r["unconverged_steps"]) for r in rows) / steps
    ratio = lam["wall_s_per_strain"] / ours["wall_time_per_strain_s"]
    cpu = float((folder / f"{point}-dilatant-cpu-s.txt").read_text()) / (ours["strain"] - start)
    end = ours["strain"] + (warm if continued else 0.0)
    print(f"| {point} | LAMMPS, 1 rank | {lam['I_R']:.4f} | {lam['phi_bulk']:.3f} | "
          f"{lam['steps_per_strain']:,.0f} | - | - | - | {lam['contacts_per_frame']:,.0f} | - | "
          f"{lam['wall_s_per_strain']:.1f} | {lam['cpu_s_per_strain']:.1f} | |")
    print(f"| {point} | dilatant, 1 thread (strain {warm:.2f}-{end:.2f}) | "
          f"{ours['inertial_number']:.4f} | {ours['phi_bulk']:.3f} | "
          f"{ours['steps_per_strain']:,.0f} | {sweeps:.0f} | "
          f"{ours.get('sweep_equivalents_per_step', sweeps):.0f} | {100 * capped:.1f}% | {contacts:,.0f} | "
          f"{ours['ns_per_contact_update']:.1f} | {ours['wall_time_per_strain_s']:.1f} | "
          f"{cpu:.1f} | {ratio:.2f} |")
PY
