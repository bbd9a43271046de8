#include "measure/cell_records.hpp"

#include <algorithm>
#include <cmath>

namespace dilatant {

namespace {

// A quantity that exists only with walls: null without them.
nlohmann::json wall_only(bool walls, double x) {
  return walls ? nlohmann::json(x) : nlohmann::json(nullptr);
}

void write_average(nlohmann::json& j, const char* key, const SteadyAverage& a, double unit = 1.0) {
  j[key] = a.mean / unit;
  j[std::string(key) + "_err"] = a.error / unit;
}

}  // namespace

StressRecord StressRecord::of(const std::vector<FlowRow>& rows, double from) {
  StressRecord s;
  s.shear = steady_average(rows, from, [](const FlowRow& r) { return invariants(r.stress).shear; });
  s.pressure =
      steady_average(rows, from, [](const FlowRow& r) { return invariants(r.stress).pressure; });
  s.n1 = steady_average(rows, from, [](const FlowRow& r) { return invariants(r.stress).n1; });
  s.n2 = steady_average(rows, from, [](const FlowRow& r) { return invariants(r.stress).n2; });
  for (std::size_t k = 0; k < s.tensor.size(); ++k)
    s.tensor[k] = steady_average(rows, from, [k](const FlowRow& r) { return r.stress[k]; }).mean;
  return s;
}

void StressRecord::write(nlohmann::json& j, double unit, double imposed_normal) const {
  write_average(j, "shear_stress_measured", shear, unit);
  write_average(j, "pressure", pressure, unit);
  write_average(j, "n1", n1, unit);
  write_average(j, "n2", n2, unit);
  if (pressure.mean > 0.0) {
    const double mu = shear.mean / pressure.mean;
    j["mu_pressure"] = mu;
    j["mu_pressure_err"] =
        std::abs(mu) * std::hypot(shear.mean != 0.0 ? shear.error / shear.mean : 0.0,
                                  pressure.error / pressure.mean);
  } else {
    j["mu_pressure"] = nullptr;
    j["mu_pressure_err"] = nullptr;
  }
  if (imposed_normal > 0.0) {
    j["mu_eff"] = shear.mean / imposed_normal;
    j["mu_eff_err"] = shear.error / imposed_normal;
    j["mu_eff_definition"] = "shear_stress_measured / normal_stress_imposed";
  } else {
    j["mu_eff"] = j["mu_pressure"];
    j["mu_eff_err"] = j["mu_pressure_err"];
    j["mu_eff_definition"] = "shear_stress_measured / pressure";
  }
  nlohmann::json rows = nlohmann::json::array();
  for (int a = 0; a < 3; ++a) {
    nlohmann::json row = nlohmann::json::array();
    for (int b = 0; b < 3; ++b) row.push_back(tensor[tensor_index(a, b)] / unit);
    rows.push_back(row);
  }
  j["stress_tensor"] = rows;  // sigma_ab, rows a = x, y, z (the branch's component)
}

ContactRecord ContactRecord::of(const std::vector<FlowRow>& rows, double from) {
  return {
      .bl = steady_average(rows, from, [](const FlowRow& r) { return r.frac_bl; }),
      .over_s_lim = steady_average(rows, from, [](const FlowRow& r) { return r.frac_over_slim; }),
      .impulsive = steady_average(rows, from, [](const FlowRow& r) { return r.frac_impulsive; }),
      .bl_persistent =
          steady_average(rows, from, [](const FlowRow& r) { return r.frac_bl_persistent; })};
}

void ContactRecord::write(nlohmann::json& j) const {
  write_average(j, "frac_bl", bl);
  j["frac_impulsive"] = impulsive.mean;
  write_average(j, "frac_bl_persistent", bl_persistent);
  j["frac_hd"] = 1.0 - bl.mean;
  j["frac_over_slim"] = over_s_lim.mean;
}

EnergyRecord EnergyRecord::of(const std::vector<FlowRow>& rows, double from) {
  EnergyRecord e;
  e.injected = steady_average(rows, from, [](const FlowRow& r) { return r.power_drive; });
  e.impacts = steady_average(rows, from, [](const FlowRow& r) { return -r.power_normal; });
  e.friction_bl = steady_average(rows, from, [](const FlowRow& r) { return -r.power_bl; });
  e.friction_hd = steady_average(rows, from, [](const FlowRow& r) { return -r.power_hd; });
  e.lubrication = steady_average(rows, from, [](const FlowRow& r) { return -r.power_lubrication; });
  e.drag = steady_average(rows, from, [](const FlowRow& r) { return -r.power_drag; });
  e.kinetic = steady_average(rows, from, [](const FlowRow& r) { return r.power_kinetic; });
  e.sliding_bl = steady_average(rows, from, [](const FlowRow& r) { return r.sliding_bl; });
  e.sliding_hd = steady_average(rows, from, [](const FlowRow& r) { return r.sliding_hd; });
  return e;
}

void EnergyRecord::write(nlohmann::json& j) const {
  write_average(j, "power_injected", injected);
  write_average(j, "power_impacts", impacts);          // perfectly inelastic normal impacts
  write_average(j, "power_friction_bl", friction_bl);  // tangential impulses at stick/BL contacts
  write_average(j, "power_friction_hd", friction_hd);
  // The fluid forces (fluid/): squeeze films between close surfaces, and the
  // drag relative to the drive's mean flow, which may also feed power in
  // (< 0) where the fluid outruns the particles.
  write_average(j, "power_lubrication", lubrication);
  write_average(j, "power_drag", drag);
  write_average(j, "power_kinetic", kinetic);  // d(KE)/dt
  j["power_sliding_bl"] = sliding_bl.mean;
  j["power_sliding_hd"] = sliding_hd.mean;
}

WallForceRecord WallForceRecord::of(const std::vector<FlowRow>& rows, double from, bool walls) {
  return {.bottom_x = steady_average(rows, from, [](const FlowRow& r) { return r.bottom_force_x; }),
          .top_z = steady_average(rows, from, [](const FlowRow& r) { return r.top_force_z; }),
          .bottom_z = steady_average(rows, from, [](const FlowRow& r) { return r.bottom_force_z; }),
          .walls = walls};
}

void WallForceRecord::write(nlohmann::json& j) const {
  j["bottom_wall_force_x"] = wall_only(walls, bottom_x.mean);
  j["bottom_wall_force_x_err"] = wall_only(walls, bottom_x.error);
  j["top_wall_force_z"] = wall_only(walls, top_z.mean);  // push of the particles on the top wall
  j["top_wall_force_z_err"] = wall_only(walls, top_z.error);
  // negative: the bottom wall is pushed down
  j["bottom_wall_force_z"] = wall_only(walls, bottom_z.mean);
  j["bottom_wall_force_z_err"] = wall_only(walls, bottom_z.error);
}

SolverRecord SolverRecord::of(const std::vector<FlowRow>& rows) {
  SolverRecord s;
  for (const FlowRow& r : rows) {
    if (s.deepest == nullptr || r.max_overlap > s.deepest->max_overlap) s.deepest = &r;
    if (r.contact_residual_step >= 0.0 &&
        (s.worst_residual == nullptr ||
         r.contact_residual_max > s.worst_residual->contact_residual_max))
      s.worst_residual = &r;
    s.unconverged += r.unconverged_steps;
    s.iterations += r.mean_iterations * r.steps;
    s.steps += r.steps;
    s.residual_max = std::max(s.residual_max, r.contact_residual_max);
    s.residual_rms_sum += r.contact_residual_rms * r.steps;
  }
  return s;
}

void SolverRecord::write(nlohmann::json& j, double overlap_tolerance) const {
  const auto step_and_bodies = [&j](const char* step_key, const char* bodies_key, double step,
                                    double i, double k) {
    j[step_key] = static_cast<long long>(step);
    j[bodies_key] = {static_cast<long long>(i), static_cast<long long>(k)};
  };
  j["max_overlap"] = max_overlap();
  // Where it was, and whether it exceeds the tolerance of docs/model.md
  // "Overlaps" (a run that does is warned about; its numbers are suspect).
  if (deepest != nullptr && deepest->max_overlap_step >= 0.0) {
    step_and_bodies("max_overlap_step", "max_overlap_bodies", deepest->max_overlap_step,
                    deepest->max_overlap_body_i, deepest->max_overlap_body_j);
  } else {
    j["max_overlap_step"] = nullptr;
    j["max_overlap_bodies"] = nullptr;
  }
  j["overlap_tolerance"] = overlap_tolerance;
  j["overlap_exceeded"] = max_overlap() > overlap_tolerance;
  j["mean_iterations"] = steps > 0.0 ? iterations / steps : 0.0;
  j["frac_steps_unconverged"] = steps > 0.0 ? unconverged / steps : 0.0;
  // The residual of the contact problem itself: the worst contact of any step,
  // and the step-mean of the RMS over contacts, in units of the load's impulse
  // sigma_ref (2 R_max)^2 dt (drivers/cell_time_step.hpp reference_stress());
  // where the worst was, so that a run that did not converge says where.
  j["contact_residual_max"] = residual_max;
  j["contact_residual_rms"] = steps > 0.0 ? residual_rms_sum / steps : 0.0;
  if (worst_residual != nullptr) {
    step_and_bodies("contact_residual_max_step", "contact_residual_max_bodies",
                    worst_residual->contact_residual_step, worst_residual->contact_residual_body_i,
                    worst_residual->contact_residual_body_j);
  } else {
    j["contact_residual_max_step"] = nullptr;
    j["contact_residual_max_bodies"] = nullptr;
  }
}

}  // namespace dilatant
