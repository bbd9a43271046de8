#pragma once
// What a run cost: wall time by stage of the step, the work of the solver in
// contact updates (one contact solved once in one sweep), and peak memory.
// Reported in summary.json so that every run is also a benchmark (bench/).
// Times cover this invocation only (a resumed run counts from its restart).
#include <chrono>
#include <nlohmann/json.hpp>

namespace dilatant {

struct StepReport;

struct RunCost {
  double wall_s = 0.0;             // whole invocation
  double build_s = 0.0;            // initial state (packing) or checkpoint load
  double detection_s = 0.0;        // contact detection, slab ordering, warm start
  double solve_s = 0.0;            // Gauss–Seidel sweeps
  double measure_s = 0.0;          // measurements, time series, snapshots (not checkpoints)
  double contact_updates = 0.0;    // local solves (a skipped open contact is not one)
  double sweep_equivalents = 0.0;  // sum over steps of contact_updates / contacts detected
  double steps = 0.0;              // steps run in this invocation
  double steps_dt_by_drive = 0.0;  // of those, steps whose dt the wall's drive bound set
  double steps_redone = 0.0;       // of those, steps whose solve was redone at half the step ...
  double halvings = 0.0;           // ... and the halvings all of them took
  double strain = 0.0;             // strain run in this invocation
  int threads = 1;

  double ns_per_contact_update() const {
    return contact_updates > 0.0 ? 1e9 * solve_s / contact_updates : 0.0;
  }
  // One more step (solver/time_stepper.hpp): its stages' times and its work.
  void add_step(const StepReport& step);
  // Its keys of summary.json: wall_time_s, threads, time_*_s,
  // ns_per_contact_update, sweep_equivalents_per_step, wall_time_per_strain_s,
  // frac_steps_dt_by_drive, steps_per_strain, steps_redone, halvings,
  // peak_memory_mib.
  void write(nlohmann::json& summary) const;
};

// Wall time since `start`, in seconds (the steady clock: never jumps).
double seconds_since(std::chrono::steady_clock::time_point start);

// Peak resident memory of this process so far, in MiB (getrusage).
double peak_memory_mib();

}  // namespace dilatant
