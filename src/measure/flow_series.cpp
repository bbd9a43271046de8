#include "measure/flow_series.hpp"

#include <fmt/format.h>

namespace dilatant {

std::string flow_csv_header() {
  return "t,strain,wall_velocity,gamma_dot,kinetic_energy,contacts,frac_bl,frac_over_slim,"
         "normal_stress,bottom_force_x,iterations,residual,dt,steps,unconverged_steps,"
         "contact_residual_max,contact_residual_rms,shear_stress_measured,pressure,n1,n2\n";
}

std::string flow_csv_row(const FlowRow& r, double lz) {
  const StressInvariants sigma = invariants(r.stress);
  return fmt::format(
      "{:.8g},{:.8g},{:.8g},{:.8g},{:.8g},{:.6g},{:.6g},{:.6g},{:.8g},{:.8g},{:.4g},"
      "{:.3e},{:.4g},{},{},{:.3e},{:.3e},{:.8g},{:.8g},{:.8g},{:.8g}\n",
      r.t, r.strain, r.wall_velocity, r.wall_velocity / lz, r.kinetic_energy, r.contacts, r.frac_bl,
      r.frac_over_slim, r.normal_stress, r.bottom_force_x, r.mean_iterations, r.max_residual,
      r.mean_dt, r.steps, r.unconverged_steps, r.contact_residual_max, r.contact_residual_rms,
      sigma.shear, sigma.pressure, sigma.n1, sigma.n2);
}

FlowRow IntervalSums::close(double t, double strain) const {
  FlowRow r;
  r.t = t;
  r.strain = strain;
  r.duration = time;
  if (time <= 0.0) return r;
  r.wall_velocity = velocity / time;
  r.kinetic_energy = kinetic_energy / time;
  r.contacts = contacts / time;
  r.frac_bl = closed > 0.0 ? boundary / closed : 0.0;
  r.frac_over_slim = closed > 0.0 ? over_s_lim / closed : 0.0;
  r.frac_impulsive = closed > 0.0 ? impulsive / closed : 0.0;
  r.frac_bl_persistent =
      closed > impulsive ? (boundary - impulsive_boundary) / (closed - impulsive) : 0.0;
  r.normal_stress = normal_stress / time;
  r.bottom_force_x = bottom_force_x / time;
  r.top_force_z = top_force_z / time;
  r.bottom_force_z = bottom_force_z / time;
  r.sliding_bl = sliding_bl / time;
  r.sliding_hd = sliding_hd / time;
  r.power_drive = work_drive / time;
  r.power_normal = work_normal / time;
  r.power_bl = work_bl / time;
  r.power_hd = work_hd / time;
  r.power_lubrication = work_lubrication / time;
  r.power_drag = work_drag / time;
  r.power_kinetic = (kinetic_end - kinetic_start) / time;
  r.mean_iterations = iterations / steps;
  r.max_residual = max_residual;
  r.mean_dt = time / steps;
  r.steps = steps;
  r.unconverged_steps = unconverged;
  r.contact_residual_max = contact_residual_max;
  r.contact_residual_rms = contact_residual_rms / steps;
  r.contact_residual_step = contact_residual_step;
  r.contact_residual_body_i = contact_residual_body_i;
  r.contact_residual_body_j = contact_residual_body_j;
  r.max_overlap = max_overlap;
  r.max_overlap_step = max_overlap_step;
  r.max_overlap_body_i = max_overlap_body_i;
  r.max_overlap_body_j = max_overlap_body_j;
  for (std::size_t k = 0; k < r.stress.size(); ++k) r.stress[k] = stress_dt[k] / time;
  return r;
}

}  // namespace dilatant
