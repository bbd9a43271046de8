#pragma once
// DIR/flowcurves.csv: one row per point of a sweep, sorted by point index.
//
// Columns, in order:
//   the swept keys, dotted (friction.mu0, fluid.lambda, ...), as in sweep.toml;
//   point        the point's index;
//   status       done | failed | pending (not run yet, running, or interrupted) |
//                skipped (above the jam of its ramp: sweep.stop_at_jam);
//   error        why a failed point failed or a skipped one was not run (one
//                line), else empty;
//   phi, mu0, lambda   the curve's labels from the configuration: phi is cell.phi
//                as requested (every point of a curve shares it; the packing's
//                own fraction is phi_realized);
//   shear_stress, gamma_dot, gamma_dot_err, eta, eta_err, valid, jammed, frac_bl,
//   frac_bl_err, frac_hd, frac_over_slim, gamma_dot_bulk, gamma_dot_gap,
//   profile_consistent, phi_realized, phi_bulk, phi_bulk_err, s_c, friction_law,
//   normal_stress, normal_stress_err, inertial_number, viscous_number, control,
//   normal_stress_imposed, box_height_mean, box_height_err,
//   box_height_fluctuation, phi_bulk_drift, phi_bulk_drift_err (the
//   pressure-imposed cell's; empty under the other controls),
//   shear_stress_measured, pressure, n1, n2, mu_eff, mu_pressure (each with
//   _err), mu_eff_definition (mu_eff is tau / P imposed under pressure
//   control, else tau / pressure; mu_pressure always the latter),
//   frac_impulsive, frac_bl_persistent, mobile_spheres, strain, steps,
//   mean_iterations, frac_steps_unconverged, wall_time_s, version
//                from the point's summary.json (paper units; docs/shear-cell.md),
//                empty until the point is done; eta is empty when it jammed;
//   sample       the flow curve the point belongs to, beside phi: "mu0=0.1", plus
//                " key=value" for every other swept key but those that place a
//                point along its curve (cell.phi, fluid.lambda,
//                cell.shear_stress, cell.shear_rate, cell.normal_stress;
//                dilatant analyze groups rows by phi and sample);
//   start        "cold" (a new packing) or the folder of the point it continues from
//                (the lowest extra point of a refinement's segment, sweep.refines:
//                the refined ramp's point's, relative to DIR);
//   dir          the point's run folder, relative to DIR;
//   jam_cold_start  for a continued point that jammed (sweep.confirm_jams):
//                jammed | flowed (its cold start in DIR/dir/cold-start/) or
//                pending; else empty.
//   jam_cold_start_phi, jam_cold_start_phi_bulk  that cold start's nominal phi
//                and the bulk fraction it reached (its summary.json);
//   jam_phi_bulk_start, jam_cold_start_phi_bulk_start  under
//                sweep.cold_start_phi = "bulk": the bulk fraction the jammed
//                point began from (the final state of the point before it) and
//                the one its cold start's packing begins with
//                (cold-start/phi_choice.json); else empty.
// Booleans are true/false, numbers the shortest text that reads back exactly;
// a field with ',' or '"' is quoted (with '"' inside turned into ').
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <vector>

#include "sweep/sweep_plan.hpp"

namespace dilatant::sweep {

enum class PointStatus { Pending, Running, Done, Failed, Skipped };
std::string_view status_name(PointStatus s);  // a running point is "pending" in the table

struct PointRecord {
  PointStatus status = PointStatus::Pending;
  std::string error;       // when failed
  nlohmann::json summary;  // when done: summary.json
  // A jam's confirmation from a cold start: its summary.json once run.
  nlohmann::json cold_start;
  // How that cold start's phi was chosen (cold_start_choice.hpp): its
  // cold-start/phi_choice.json under sweep.cold_start_phi = "bulk", else null.
  nlohmann::json cold_start_choice;
};

// The point ran and jammed.
bool jammed(const PointRecord& r);

// `out` is the sweep's folder: a refinement's `start` is named relative to it
// (absolute when `out` is empty).
std::string flowcurves_csv(const SweepPlan& plan, const std::vector<PointRecord>& records,
                           const std::filesystem::path& out = {});

// The curve label of the `sample` column.
std::string sample_label(const SweepPlan& plan, const SweepPoint& point);

}  // namespace dilatant::sweep
