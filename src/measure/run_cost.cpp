#include "measure/run_cost.hpp"

#include <sys/resource.h>

#include "solver/time_stepper.hpp"

namespace dilatant {

void RunCost::add_step(const StepReport& step) {
  detection_s += step.detection_seconds;
  solve_s += step.solve_seconds;
  contact_updates += step.solve.contact_visits;
  if (step.contacts_detected > 0)
    sweep_equivalents += step.solve.contact_visits / double(step.contacts_detected);
  // The undone attempts' work is work (solver/time_stepper.hpp).
  sweep_equivalents += step.redone_sweep_equivalents;
  steps_redone += step.redos > 0 ? 1.0 : 0.0;
  halvings += step.redos;
  steps += 1.0;
}

void RunCost::write(nlohmann::json& j) const {
  j["wall_time_s"] = wall_s;
  j["threads"] = threads;
  j["time_build_s"] = build_s;
  j["time_detection_s"] = detection_s;
  j["time_solve_s"] = solve_s;
  j["time_measure_s"] = measure_s;
  j["time_other_s"] = wall_s - build_s - detection_s - solve_s - measure_s;
  j["ns_per_contact_update"] = ns_per_contact_update();
  // Work of the solver per step in passes over all detected contacts (= sweeps
  // per step when every sweep visits every contact).
  j["sweep_equivalents_per_step"] = steps > 0.0 ? sweep_equivalents / steps : 0.0;
  j["wall_time_per_strain_s"] = strain > 0.0 ? (wall_s - build_s) / strain : 0.0;
  // Which rule of the automatic step (drivers/cell_time_step.cpp) limited it:
  // the drive's bound, or the fastest body's speed in the rest of the steps.
  j["frac_steps_dt_by_drive"] = steps > 0.0 ? steps_dt_by_drive / steps : 0.0;
  j["steps_per_strain"] = strain > 0.0 ? steps / strain : 0.0;
  // Steps whose solve did not converge and were redone at half the step
  // (solver/time_stepper.hpp); their undone work is in the sweep-equivalents.
  j["steps_redone"] = steps_redone;
  j["halvings"] = halvings;
  j["peak_memory_mib"] = peak_memory_mib();
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

double peak_memory_mib() {
  rusage usage{};
  if (getrusage(RUSAGE_SELF, &usage) != 0) return 0.0;
  return static_cast<double>(usage.ru_maxrss) / 1024.0;  // ru_maxrss is in KiB on Linux
}

}  // namespace dilatant
