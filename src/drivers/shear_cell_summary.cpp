#include "drivers/shear_cell_summary.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "dilatant/version.hpp"
#include "drivers/shear_cell.hpp"
#include "measure/bulk_fraction.hpp"
#include "measure/cell_records.hpp"
#include "measure/rheology.hpp"
#include "measure/steadiness.hpp"

namespace dilatant {

double bulk_fraction(const ShearCellState& s) {
  const BulkRegion region = s.drive->bulk_region(s.world);
  // Without walls the box's fraction, exactly; its height H may have moved
  // from the height it was built with (pressure control): phi_box H0 / H.
  return region.whole_box ? s.geometry.phi_box * s.geometry.gap_height / s.world.box.length[2]
                          : slab_volume_fraction(s.world, region.z_lo, region.z_hi);
}

namespace {

// The critical-load law's scales (docs/model.md "Friction"): F* as given (the
// paper's force unit eta_f^2/rho_p) and in code units; the onset stress
// sigma* = F*/R^2 in the paper's units and over the applied stress; and the
// lambda at which the applied stress, lambda^2 in the paper's units, meets it.
// Null under the other laws.
void write_critical_load(nlohmann::json& j, const Config& config, const CellUnits& u) {
  const bool law = config.friction.law == FrictionLawKind::CriticalLoad;
  const double radius = config.cell()->radius_max;
  const double sigma_star = config.critical_load() / (radius * radius);
  const double over_tau = sigma_star / config.cell()->shear_stress;
  const auto value = [law](double v) { return law ? nlohmann::json(v) : nlohmann::json(nullptr); };
  j["critical_load"] = value(config.friction.critical_load);
  j["critical_load_code"] = value(config.critical_load());
  j["onset_stress"] = value(sigma_star / u.stress_unit);
  j["onset_stress_over_tau"] = value(over_tau);
  j["lambda_at_onset_stress"] = value(u.lambda * std::sqrt(over_tau));
}

// Under pressure control (docs/shear-cell.md "The pressure-imposed cell"): the
// normal stress imposed, and the box height H the cell ends with and its
// steady mean. A row keeps the box's phi_bulk = phi_box H0 / H, so each row's
// H = H0 phi_box / phi_bulk; the mean is over the rows past the transient (code
// units, R), and so is the fluctuation, the rows' standard deviation of H over
// its mean, which this returns (0 without rows). Null under the other controls
// (the height is cell.size's).
double write_box_height(nlohmann::json& j, const Config& config, const CellUnits& u,
                        const ShearCellState& s, double from) {
  const CellConfig& cell = *config.cell();
  const bool pressure = cell.control == ShearControl::Pressure;
  const double h0_phi = s.geometry.gap_height * s.geometry.phi_box;
  const auto height = steady_average(s.measurements.rows, from, [&](const FlowRow& r) {
    return r.phi_bulk > 0.0 ? h0_phi / r.phi_bulk : 0.0;
  });
  const auto value = [&](double x) {
    return pressure ? nlohmann::json(x) : nlohmann::json(nullptr);
  };
  j["normal_stress_imposed"] = value(cell.normal_stress / u.stress_unit);
  j["box_height"] = value(s.world.box.length[2]);
  const bool averaged = pressure && height.samples > 0;
  j["box_height_mean"] = averaged ? nlohmann::json(height.mean) : nlohmann::json(nullptr);
  j["box_height_err"] = averaged ? nlohmann::json(height.error) : nlohmann::json(nullptr);
  double n = 0.0, sum_sq = 0.0;
  for (const FlowRow& r : s.measurements.rows) {
    if (r.strain <= from || !(r.phi_bulk > 0.0)) continue;
    const double h = h0_phi / r.phi_bulk - height.mean;
    n += 1.0;
    sum_sq += h * h;
  }
  const double fluctuation = averaged && n > 0.0 ? std::sqrt(sum_sq / n) / height.mean : 0.0;
  j["box_height_fluctuation"] = averaged ? nlohmann::json(fluctuation) : nlohmann::json(nullptr);
  return fluctuation;
}

// The largest standard deviation of the box height, over its mean, of a
// pressure-controlled point that counts as valid.
constexpr double kLidFluctuationLimit = 0.05;

}  // namespace

nlohmann::json cell_summary(const Config& config, const CellUnits& u, const ShearCellState& s,
                            const RunCost& cost) {
  const CellConfig& cell = *config.cell();
  const CellMeasurements& m = s.measurements;
  const std::vector<FlowRow>& rows = m.rows;
  const double from = config.run.transient_strain;
  const Drive& drive = *s.drive;
  const bool walls = drive.bounded_by_walls();
  const bool rate = cell.control != ShearControl::Stress;  // rate or pressure
  const bool pressure = cell.control == ShearControl::Pressure;
  const CellRecords records = m.records(from,
                                        {.height = cell.size[2],
                                         .shear_stress = cell.shear_stress,
                                         .rate_controlled = rate,
                                         .radius = cell.radius_max,
                                         .density = config.density},
                                        u, walls);
  const Rheology& rheology = records.rheology;
  const SteadyAverage& v = rheology.wall_velocity;
  const auto phi_bulk = steady_average(rows, from, [](const FlowRow& r) { return r.phi_bulk; });

  // Bulk shear rate: slope of the profile over the drive's bulk region (the
  // central half of the gap; the whole Lees–Edwards box, which has no wall
  // layers to leave out); its deviation from a line over the whole flow.
  const BulkRegion region = drive.bulk_region(s.world);
  const LinearFit bulk = m.profile.fit(region.z_lo, region.z_hi);
  const LinearFit whole = m.profile.fit(region.flow_lo, region.flow_hi);
  // Without slip the profile is linear between the walls' mean surfaces, so the
  // bulk rate expected is V / (Lz - 2 r_w), not the paper's V / Lz (7% lower in
  // the paper's cell). Agreement within 2 error bars of V, and never closer
  // than 10% (the profile's own statistical error is not yet estimated), counts.
  const double gdot_gap = v.mean / s.geometry.gap_height;
  const bool profile_consistent =
      rheology.shear_rate > 0.0 &&
      std::abs(bulk.slope - gdot_gap) <= std::max(0.1, 2.0 * rheology.relative_error) * gdot_gap;

  nlohmann::json j;
  j["version"] = kVersion;
  j["mode"] = "cell";
  j["lambda"] = u.lambda;
  j["eta_f"] = u.eta_f;
  j["mu0"] = config.friction.mu0;
  j["s_c"] = config.friction.s_c;
  j["s_lim"] = config.friction.s_lim;
  j["friction_law"] = friction_law_name(config.friction.law);
  write_critical_load(j, config, u);
  j["beyond_s_lim"] = config.friction.viscous_beyond_s_lim ? "viscous" : "cap";
  j["lubrication"] = config.fluid.lubrication == LubricationKind::Normal ? "normal" : "none";
  j["drag"] = config.fluid.drag == DragKind::Stokes ? "stokes" : "none";
  // The boundary (docs/shear-cell.md "The Lees–Edwards cell"): without walls
  // the wall-only fields are null, and wall_velocity is the images' speed
  // V = gamma_dot Lz.
  j["boundary"] = drive.name();
  j["control"] = pressure ? "pressure" : rate ? "rate" : "stress";
  const double height_fluctuation = write_box_height(j, config, u, s, from);
  // cell.phi counts as cell.phi_definition says; both counts are reported
  // (without walls: the box, exactly).
  const bool box = !walls || cell.phi_definition == PhiDefinition::Box;
  j["phi"] = box ? s.geometry.phi_box : s.geometry.phi;
  j["phi_requested"] = cell.phi;
  j["phi_definition"] = box ? "box" : "between-walls";
  j["phi_between_walls"] = walls ? nlohmann::json(s.geometry.phi) : nlohmann::json(nullptr);
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
  j["wall_radius_mean"] =
      walls ? nlohmann::json(s.geometry.wall_radius_mean) : nlohmann::json(nullptr);
  j["jammed"] = s.jam.jammed;
  // gamma_dot, eta and tau, once for either control (measure/rheology.hpp).
  write_rheology(j, rheology, u, s.jam.jammed);
  j["gamma_dot_bulk"] = bulk.slope / u.rate_unit;
  j["gamma_dot_gap"] = s.jam.jammed ? 0.0 : gdot_gap / u.rate_unit;
  j["profile_consistent"] = profile_consistent;
  j["profile_max_deviation"] = v.mean != 0.0 ? whole.max_deviation / std::abs(v.mean) : 0.0;
  // mu_eff: Boyer et al.'s tau / P under pressure control, else sigma_zx / p
  // (measure/cell_records.hpp); mu_pressure is sigma_zx / p under every control.
  records.stress.write(j, u.stress_unit, pressure ? cell.normal_stress : 0.0);
  records.contacts.write(j);
  // s_lim bounds the lubrication picture, so it limits validity only for a law
  // that reads s: the coulomb control has no lubrication to break down.
  const bool lubricated = config.friction.law == FrictionLawKind::Stribeck;
  // A window whose wall speed still drifts is not a steady point (measure/steadiness.hpp);
  // one too short to tell (null) is not flagged.
  const Drift drift = wall_speed_drift(rows, from);
  const bool jammed = s.jam.jammed;
  // Under pressure control the wall speed is imposed; the box height (phi_bulk)
  // is what may still drift.
  const Drift phi_drift = volume_fraction_drift(rows, from);
  const bool height_drifting = pressure && !jammed && phi_drift.known && !phi_drift.steady;
  j["phi_bulk_drift"] = pressure ? nlohmann::json(phi_drift.change) : nlohmann::json(nullptr);
  j["phi_bulk_drift_err"] = pressure ? nlohmann::json(phi_drift.error) : nlohmann::json(nullptr);
  const bool drifting = !jammed && drift.known && !drift.steady;
  j["steady"] = jammed || !drift.known ? nlohmann::json(nullptr)
                                       : nlohmann::json(drift.steady && !height_drifting);
  j["wall_velocity_drift"] = drift.change;  // second half of the window minus first, relative
  j["wall_velocity_drift_err"] = drift.error;
  // Why a point is not valid, in words a user can act on (the CLI's warning
  // repeats them; docs/shear-cell.md "Validity"): none, exactly when valid.
  std::vector<std::string> invalid;
  if (jammed) invalid.emplace_back("jammed: the flow stopped, no steady flow to measure");
  if (lubricated && records.contacts.over_s_lim.mean > 0.05)
    invalid.push_back(fmt::format(
        "{:.0f}% of the contacts are beyond friction.s_lim (at most 5%): outside the lubrication "
        "picture",
        100.0 * records.contacts.over_s_lim.mean));
  if (!profile_consistent)
    invalid.emplace_back(
        "the velocity profile is not linear in the bulk (gamma_dot_bulk and gamma_dot_gap "
        "disagree): the shear localises");
  if (drifting)
    invalid.push_back(fmt::format(
        "not steady: the wall speed drifted by {:+.0f}% +- {:.0f}% over the averaging window "
        "(run longer, or raise run.transient_strain)",
        100.0 * drift.change, 100.0 * drift.error));
  // A lid too light for the flow bounces (docs/shear-cell.md "Films and
  // drag"): its height swings far about a mean that may look steady.
  if (pressure && height_fluctuation > kLidFluctuationLimit)
    invalid.push_back(fmt::format(
        "the box height fluctuates by {:.0f}% of its mean (at most {:.0f}%): the lid bounces; "
        "make it heavier (cell.boundary_mass)",
        100.0 * height_fluctuation, 100.0 * kLidFluctuationLimit));
  if (height_drifting)
    invalid.push_back(fmt::format(
        "not steady: phi_bulk (the box height) drifted by {:+.1f}% +- {:.1f}% over the averaging "
        "window (run longer, raise run.transient_strain, or make the lid heavier: "
        "cell.boundary_mass)",
        100.0 * phi_drift.change, 100.0 * phi_drift.error));
  j["valid"] = invalid.empty();
  j["invalid_reasons"] = invalid;
  records.wall_forces.write(j);
  records.solver.write(j, ShearCell::kOverlapTolerance * cell.radius_min);
  // What the solver stopped on, and the stress its residual's unit is taken
  // from: the applied one, or under rate control the measured one (at least
  // the Bagnold and viscous stresses of the imposed rate).
  j["solver_convergence"] =
      config.solver.convergence == Convergence::Residual ? "residual" : "change";
  j["contact_residual_reference"] = rate ? "measured" : "applied";
  // tau Lx Ly on the top wall or the Lees–Edwards boundary; none under rate control.
  j["applied_force_x"] = rate ? nlohmann::json(nullptr)
                              : nlohmann::json(cell.shear_stress * cell.size[0] * cell.size[1]);
  // Energy budget of the steady state, code units (force x velocity): the drive's
  // power equals the dissipation in impacts and friction plus d(KE)/dt.
  records.energy.write(j);
  j["strain"] = s.strain;
  j["transient_strain"] = from;  // the averages are over the strain past it
  j["time"] = s.world.time;
  j["steps"] = s.steps;
  j["steady_samples"] = v.samples;
  // The cost of this invocation (bench/ reads these; see measure/run_cost.hpp).
  cost.write(j);
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
