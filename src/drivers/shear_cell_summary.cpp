#include "drivers/shear_cell_summary.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "dilatant/version.hpp"
#include "drivers/shear_cell.hpp"
#include "measure/bulk_fraction.hpp"
#include "measure/rheology.hpp"
#include "measure/steadiness.hpp"

namespace dilatant {

namespace {

// The particle stress tensor's steady averages (measure/particle_stress.hpp),
// in the paper's units. mu_eff is the ratio of the means, its error
// propagated from both as if independent.
void add_stress(nlohmann::json& j, const std::vector<FlowRow>& rows, double from, double unit) {
  const auto average = [&](auto field) { return steady_average(rows, from, field); };
  const auto shear = average([](const FlowRow& r) { return invariants(r.stress).shear; });
  const auto pressure = average([](const FlowRow& r) { return invariants(r.stress).pressure; });
  const auto n1 = average([](const FlowRow& r) { return invariants(r.stress).n1; });
  const auto n2 = average([](const FlowRow& r) { return invariants(r.stress).n2; });
  j["shear_stress_measured"] = shear.mean / unit;
  j["shear_stress_measured_err"] = shear.error / unit;
  j["pressure"] = pressure.mean / unit;
  j["pressure_err"] = pressure.error / unit;
  j["n1"] = n1.mean / unit;
  j["n1_err"] = n1.error / unit;
  j["n2"] = n2.mean / unit;
  j["n2_err"] = n2.error / unit;
  if (pressure.mean > 0.0) {
    const double mu = shear.mean / pressure.mean;
    j["mu_eff"] = mu;
    j["mu_eff_err"] = std::abs(mu) * std::hypot(shear.mean != 0.0 ? shear.error / shear.mean : 0.0,
                                                pressure.error / pressure.mean);
  } else {
    j["mu_eff"] = nullptr;
    j["mu_eff_err"] = nullptr;
  }
  nlohmann::json tensor = nlohmann::json::array();
  for (int a = 0; a < 3; ++a) {
    nlohmann::json row = nlohmann::json::array();
    for (int b = 0; b < 3; ++b) {
      const int k = tensor_index(a, b);
      row.push_back(average([k](const FlowRow& r) { return r.stress[k]; }).mean / unit);
    }
    tensor.push_back(row);
  }
  j["stress_tensor"] = tensor;  // sigma_ab, rows a = x, y, z (the branch's component)
}

}  // namespace

double bulk_fraction(const ShearCellState& s) {
  const BulkRegion region = s.drive->bulk_region(s.world);
  return region.whole_box ? s.geometry.phi_box
                          : slab_volume_fraction(s.world, region.z_lo, region.z_hi);
}

nlohmann::json cell_summary(const Config& config, const CellUnits& u, const ShearCellState& s,
                            const RunCost& cost) {
  const CellConfig& cell = *config.cell();
  const double lz = cell.size[2], area = cell.size[0] * cell.size[1];
  const double from = config.run.transient_strain;
  const Rheology rheology = steady_rheology(s.rows, from,
                                            {.height = lz,
                                             .shear_stress = cell.shear_stress,
                                             .radius = cell.radius_max,
                                             .density = config.density},
                                            u);
  const SteadyAverage& v = rheology.wall_velocity;
  const SteadyAverage& p = rheology.normal_stress;
  const auto bl = steady_average(s.rows, from, [](const FlowRow& r) { return r.frac_bl; });
  const auto over = steady_average(s.rows, from, [](const FlowRow& r) { return r.frac_over_slim; });
  const auto phi_bulk = steady_average(s.rows, from, [](const FlowRow& r) { return r.phi_bulk; });
  const auto fz_top = steady_average(s.rows, from, [](const FlowRow& r) { return r.top_force_z; });
  const auto fz_bottom =
      steady_average(s.rows, from, [](const FlowRow& r) { return r.bottom_force_z; });
  const FlowRow* deepest = nullptr;  // the row holding the run's largest overlap
  for (const FlowRow& r : s.rows)
    if (deepest == nullptr || r.max_overlap > deepest->max_overlap) deepest = &r;
  const double max_overlap = deepest != nullptr ? deepest->max_overlap : 0.0;
  const auto fx = steady_average(s.rows, from, [](const FlowRow& r) { return r.bottom_force_x; });
  const auto sliding_bl =
      steady_average(s.rows, from, [](const FlowRow& r) { return r.sliding_bl; });
  const auto sliding_hd =
      steady_average(s.rows, from, [](const FlowRow& r) { return r.sliding_hd; });
  const auto p_drive = steady_average(s.rows, from, [](const FlowRow& r) { return r.power_drive; });
  const auto p_normal =
      steady_average(s.rows, from, [](const FlowRow& r) { return -r.power_normal; });
  const auto p_bl = steady_average(s.rows, from, [](const FlowRow& r) { return -r.power_bl; });
  const auto p_hd = steady_average(s.rows, from, [](const FlowRow& r) { return -r.power_hd; });
  const auto p_lubrication =
      steady_average(s.rows, from, [](const FlowRow& r) { return -r.power_lubrication; });
  const auto p_drag = steady_average(s.rows, from, [](const FlowRow& r) { return -r.power_drag; });
  const auto p_kinetic =
      steady_average(s.rows, from, [](const FlowRow& r) { return r.power_kinetic; });
  double unconverged = 0.0, iterations = 0.0, steps = 0.0;
  double residual_max = 0.0, residual_rms = 0.0;
  const FlowRow* worst = nullptr;  // the row holding the run's largest contact residual
  for (const FlowRow& r : s.rows) {
    if (r.contact_residual_step >= 0.0 &&
        (worst == nullptr || r.contact_residual_max > worst->contact_residual_max))
      worst = &r;
    unconverged += r.unconverged_steps;
    iterations += r.mean_iterations * r.steps;
    steps += r.steps;
    residual_max = std::max(residual_max, r.contact_residual_max);
    residual_rms += r.contact_residual_rms * r.steps;
  }

  const double gdot_code = rheology.shear_rate;
  const Drive& drive = *s.drive;
  const bool walls = drive.bounded_by_walls();
  // Bulk shear rate: slope of the profile over the drive's bulk region (the
  // central half of the gap; the whole Lees–Edwards box, which has no wall
  // layers to leave out); its deviation from a line over the whole flow.
  const BulkRegion region = drive.bulk_region(s.world);
  const LinearFit bulk = s.profile.fit(region.z_lo, region.z_hi);
  const LinearFit whole = s.profile.fit(region.flow_lo, region.flow_hi);
  const double rel_err = rheology.relative_error;
  // Without slip the profile is linear between the walls' mean surfaces, so the
  // bulk rate expected is V / (Lz - 2 r_w), not the paper's V / Lz (7% lower in
  // the paper's cell). Agreement within 2 error bars, and never closer than 10%
  // (the profile's own statistical error is not yet estimated), counts.
  const double gdot_gap = v.mean / s.geometry.gap_height;
  const bool profile_consistent =
      gdot_code > 0.0 && std::abs(bulk.slope - gdot_gap) <= std::max(0.1, 2.0 * rel_err) * gdot_gap;

  nlohmann::json j;
  j["version"] = kVersion;
  j["mode"] = "cell";
  j["lambda"] = u.lambda;
  j["eta_f"] = u.eta_f;
  j["mu0"] = config.friction.mu0;
  j["s_c"] = config.friction.s_c;
  j["s_lim"] = config.friction.s_lim;
  j["friction_law"] = config.friction.law == FrictionLawKind::Coulomb ? "coulomb" : "stribeck";
  j["beyond_s_lim"] = config.friction.viscous_beyond_s_lim ? "viscous" : "cap";
  j["lubrication"] = config.fluid.lubrication == LubricationKind::Normal ? "normal" : "none";
  j["drag"] = config.fluid.drag == DragKind::Stokes ? "stokes" : "none";
  // The boundary (docs/shear-cell.md "The Lees–Edwards cell"): without walls
  // the wall-only fields below are null, and wall_velocity is the images'
  // speed V = gamma_dot Lz.
  j["boundary"] = drive.name();
  const bool rate = cell.control == ShearControl::Rate;
  j["control"] = rate ? "rate" : "stress";
  // cell.phi counts as cell.phi_definition says; both counts are reported
  // (without walls: the box, exactly).
  const bool box = !walls || cell.phi_definition == PhiDefinition::Box;
  j["phi"] = box ? s.geometry.phi_box : s.geometry.phi;
  j["phi_requested"] = cell.phi;
  j["phi_definition"] = box ? "box" : "between-walls";
  const auto wall_only = [walls](double x) {
    return walls ? nlohmann::json(x) : nlohmann::json(nullptr);
  };
  j["phi_between_walls"] = wall_only(s.geometry.phi);
  j["phi_box"] = s.geometry.phi_box;
  if (phi_bulk.samples > 0) {
    j["phi_bulk"] = phi_bulk.mean;  // central half of the gap, steady-state average
    j["phi_bulk_err"] = phi_bulk.error;
  } else {
    // No row after the transient (a jam stops the wall before it): the packing
    // the run ends in still has a bulk fraction, from its final state.
    j["phi_bulk"] = bulk_fraction(s);
    j["phi_bulk_err"] = nullptr;
  }
  j["mobile_spheres"] = s.geometry.mobile_count;
  j["wall_radius_mean"] = wall_only(s.geometry.wall_radius_mean);
  j["shear_stress"] = cell.shear_stress / u.stress_unit;
  j["jammed"] = s.jammed;
  if (s.jammed) {
    j["gamma_dot"] = 0.0;
    j["gamma_dot_err"] = 0.0;
    j["eta"] = nullptr;
    j["eta_err"] = nullptr;
  } else {
    j["gamma_dot"] = gdot_code / u.rate_unit;
    j["gamma_dot_err"] = rheology.shear_rate_err / u.rate_unit;
    j["eta"] = rheology.viscosity;
    j["eta_err"] = rheology.viscosity_err;
  }
  j["wall_velocity"] = v.mean;  // code units, sqrt(tau/rho_p)
  j["wall_velocity_err"] = v.error;
  j["gamma_dot_bulk"] = bulk.slope / u.rate_unit;
  j["gamma_dot_gap"] = s.jammed ? 0.0 : gdot_gap / u.rate_unit;
  j["profile_consistent"] = profile_consistent;
  j["profile_max_deviation"] = v.mean != 0.0 ? whole.max_deviation / std::abs(v.mean) : 0.0;
  j["normal_stress"] = p.mean / u.stress_unit;
  j["normal_stress_err"] = p.error / u.stress_unit;
  add_stress(j, s.rows, from, u.stress_unit);
  if (rate) {
    // Rate control imposes gamma_dot (its error is zero: V is fixed) and
    // measures the stress: the viscosity is the measured sigma_zx over it.
    const double tau = j["shear_stress_measured"].get<double>() * u.stress_unit;
    const double tau_err = j["shear_stress_measured_err"].get<double>() * u.stress_unit;
    j["shear_stress"] = j["shear_stress_measured"];
    if (!s.jammed) {
      j["eta"] = relative_viscosity(tau, gdot_code, u.eta_f);
      j["eta_err"] = relative_viscosity(tau_err, gdot_code, u.eta_f);
    }
  }
  j["inertial_number"] = rheology.inertial_number;
  j["viscous_number"] = rheology.viscous_number;
  j["frac_bl"] = bl.mean;
  j["frac_bl_err"] = bl.error;
  const auto impulsive =
      steady_average(s.rows, from, [](const FlowRow& r) { return r.frac_impulsive; });
  const auto bl_persistent =
      steady_average(s.rows, from, [](const FlowRow& r) { return r.frac_bl_persistent; });
  j["frac_impulsive"] = impulsive.mean;
  j["frac_bl_persistent"] = bl_persistent.mean;
  j["frac_bl_persistent_err"] = bl_persistent.error;
  j["frac_hd"] = 1.0 - bl.mean;
  j["frac_over_slim"] = over.mean;
  // s_lim bounds the lubrication picture, so it limits validity only for a law
  // that reads s: the coulomb control has no lubrication to break down.
  const bool lubricated = config.friction.law == FrictionLawKind::Stribeck;
  // A window whose wall speed still drifts is not a steady point (measure/steadiness.hpp);
  // one too short to tell (null) is not flagged.
  const Drift drift = wall_speed_drift(s.rows, from);
  const bool drifting = !s.jammed && drift.known && !drift.steady;
  j["steady"] = s.jammed || !drift.known ? nlohmann::json(nullptr) : nlohmann::json(drift.steady);
  j["wall_velocity_drift"] = drift.change;  // second half of the window minus first, relative
  j["wall_velocity_drift_err"] = drift.error;
  j["valid"] = !s.jammed && (!lubricated || over.mean <= 0.05) && profile_consistent && !drifting;
  j["bottom_wall_force_x"] = wall_only(fx.mean);
  j["bottom_wall_force_x_err"] = wall_only(fx.error);
  j["top_wall_force_z"] = wall_only(fz_top.mean);  // push of the particles on the top wall
  j["top_wall_force_z_err"] = wall_only(fz_top.error);
  j["bottom_wall_force_z"] = wall_only(fz_bottom.mean);  // negative: the bottom wall is pushed down
  j["bottom_wall_force_z_err"] = wall_only(fz_bottom.error);
  j["max_overlap"] = max_overlap;
  // Where it was (step, and the bodies' ids; a plane k as -(k+1)), and whether
  // it exceeds the tolerance of docs/model.md "Overlaps" (a run that does is
  // warned about; its numbers are suspect).
  if (deepest != nullptr && deepest->max_overlap_step >= 0.0) {
    j["max_overlap_step"] = static_cast<long long>(deepest->max_overlap_step);
    j["max_overlap_bodies"] = {static_cast<long long>(deepest->max_overlap_body_i),
                               static_cast<long long>(deepest->max_overlap_body_j)};
  } else {
    j["max_overlap_step"] = nullptr;
    j["max_overlap_bodies"] = nullptr;
  }
  j["overlap_tolerance"] = ShearCell::kOverlapTolerance * cell.radius_min;
  j["overlap_exceeded"] = max_overlap > ShearCell::kOverlapTolerance * cell.radius_min;
  // tau Lx Ly on the top wall or the Lees–Edwards boundary; none under rate control.
  j["applied_force_x"] = rate ? nlohmann::json(nullptr) : nlohmann::json(cell.shear_stress * area);
  // Energy budget of the steady state, code units (force x velocity): the drive's
  // power equals the dissipation in impacts and friction plus d(KE)/dt.
  j["power_injected"] = p_drive.mean;
  j["power_injected_err"] = p_drive.error;
  j["power_impacts"] = p_normal.mean;  // perfectly inelastic normal impacts
  j["power_impacts_err"] = p_normal.error;
  j["power_friction_bl"] = p_bl.mean;  // tangential impulses at stick/BL contacts
  j["power_friction_bl_err"] = p_bl.error;
  j["power_friction_hd"] = p_hd.mean;
  j["power_friction_hd_err"] = p_hd.error;
  // The fluid forces (fluid/): squeeze films between close surfaces, and the
  // drag relative to the walls' linear profile, which may also feed power in
  // (< 0) where the fluid outruns the particles.
  j["power_lubrication"] = p_lubrication.mean;
  j["power_lubrication_err"] = p_lubrication.error;
  j["power_drag"] = p_drag.mean;
  j["power_drag_err"] = p_drag.error;
  j["power_kinetic"] = p_kinetic.mean;  // d(KE)/dt
  j["power_kinetic_err"] = p_kinetic.error;
  // |F_t| v_s at particle-particle contacts: the continuous sliding dissipation.
  j["power_sliding_bl"] = sliding_bl.mean;
  j["power_sliding_hd"] = sliding_hd.mean;
  j["strain"] = s.strain;
  j["time"] = s.world.time;
  j["steps"] = s.steps;
  j["mean_iterations"] = steps > 0.0 ? iterations / steps : 0.0;
  j["frac_steps_unconverged"] = steps > 0.0 ? unconverged / steps : 0.0;
  // The residual of the contact problem itself (solver/contact_residual.hpp):
  // the worst contact of any step, and the step-mean of the RMS over contacts,
  // relative to the typical contact impulse.
  j["contact_residual_max"] = residual_max;
  j["contact_residual_rms"] = steps > 0.0 ? residual_rms / steps : 0.0;
  // Where the worst was: the step and the contact's bodies (ids; a plane k as
  // -(k+1)), so that a run that did not converge says where.
  if (worst != nullptr) {
    j["contact_residual_max_step"] = static_cast<long long>(worst->contact_residual_step);
    j["contact_residual_max_bodies"] = {static_cast<long long>(worst->contact_residual_body_i),
                                        static_cast<long long>(worst->contact_residual_body_j)};
  } else {
    j["contact_residual_max_step"] = nullptr;
    j["contact_residual_max_bodies"] = nullptr;
  }
  j["steady_samples"] = v.samples;
  j["wall_time_s"] = cost.wall_s;
  // The cost of this invocation (bench/ reads these; see measure/run_cost.hpp).
  j["threads"] = cost.threads;
  j["time_build_s"] = cost.build_s;
  j["time_detection_s"] = cost.detection_s;
  j["time_solve_s"] = cost.solve_s;
  j["time_measure_s"] = cost.measure_s;
  j["time_other_s"] = cost.wall_s - cost.build_s - cost.detection_s - cost.solve_s - cost.measure_s;
  j["ns_per_contact_update"] = cost.ns_per_contact_update();
  // Work of the solver per step in passes over all detected contacts (= sweeps
  // per step when every sweep visits every contact).
  j["sweep_equivalents_per_step"] = cost.steps > 0.0 ? cost.sweep_equivalents / cost.steps : 0.0;
  j["wall_time_per_strain_s"] =
      cost.strain > 0.0 ? (cost.wall_s - cost.build_s) / cost.strain : 0.0;
  // Which rule of the automatic step (drivers/shear_cell.cpp) limited it: the
  // drive's bound, or the fastest body's speed in the rest of the steps.
  j["frac_steps_dt_by_drive"] = cost.steps > 0.0 ? cost.steps_dt_by_drive / cost.steps : 0.0;
  j["steps_per_strain"] = cost.strain > 0.0 ? cost.steps / cost.strain : 0.0;
  j["peak_memory_mib"] = peak_memory_mib();
  return j;
}

std::string sommerfeld_histogram_csv(const SommerfeldHistogram& h) {
  double total = h.sticking + h.below + h.above;
  for (double c : h.count) total += c;
  const double norm = total > 0.0 ? 1.0 / total : 0.0;
  std::string out = "s_low,s_high,count,fraction\n";
  fmt::format_to(std::back_inserter(out), "0,0,{},{:.6g}\n", h.sticking, h.sticking * norm);
  fmt::format_to(std::back_inserter(out), "0,{:.6g},{},{:.6g}\n",
                 SommerfeldHistogram::bin_lower_edge(0), h.below, h.below * norm);
  for (int k = 0; k < SommerfeldHistogram::kBins; ++k) {
    fmt::format_to(std::back_inserter(out), "{:.6g},{:.6g},{},{:.6g}\n",
                   SommerfeldHistogram::bin_lower_edge(k),
                   SommerfeldHistogram::bin_lower_edge(k + 1), h.count[k], h.count[k] * norm);
  }
  fmt::format_to(std::back_inserter(out), "{:.6g},inf,{},{:.6g}\n",
                 SommerfeldHistogram::bin_lower_edge(SommerfeldHistogram::kBins), h.above,
                 h.above * norm);
  return out;
}

}  // namespace dilatant
