// The shear cell's output files (docs/shear-cell.md "Output"), each written
// atomically: the checkpoint, ParaView snapshots, the time series and the
// end-of-run results.
#include <fmt/format.h>

#include "drivers/shear_cell.hpp"
#include "drivers/shear_cell_summary.hpp"
#include "io/atomic_file.hpp"
#include "io/contacts_csv.hpp"
#include "io/vtk_writer.hpp"
#include "measure/rheology.hpp"
#include "measure/steadiness.hpp"

namespace dilatant {

std::string ShearCell::checkpoint_bytes() {
  state_.contact_memory = stepper_.contact_memory();
  return dilatant::checkpoint_bytes(state_);
}

void ShearCell::write_checkpoint(const std::filesystem::path& file) {
  state_.contact_memory = stepper_.contact_memory();
  save_checkpoint(file, state_);
  state_.schedules.checkpoints.advance_past(state_.strain);
}

void ShearCell::write_snapshot(const std::filesystem::path& out) {
  ShearCellState& s = state_;
  const auto k = s.snapshot_strains.size();
  std::filesystem::create_directories(out / "snapshots");
  const auto particles = fmt::format("snapshots/particles_{:04d}.vtp", k);
  const auto network = fmt::format("snapshots/contacts_{:04d}.vtp", k);
  // Each body's group is its owner (boundary/wall_owner.hpp); without walls
  // every body is a particle, drawn at its wrapped position in the box.
  write_particles_vtp(out / particles, s.world, s.world.bodies.owner);
  write_contacts_vtp(out / network, s.world, stepper_.contacts(), s.dt);
  s.snapshot_strains.push_back(s.strain);
  // The collection's "timestep" is the strain at the snapshot.
  PvdCollection pvd(out / "cell.pvd");
  for (std::size_t n = 0; n < s.snapshot_strains.size(); ++n) {
    pvd.add(s.snapshot_strains[n], fmt::format("snapshots/particles_{:04d}.vtp", n), 0);
    pvd.add(s.snapshot_strains[n], fmt::format("snapshots/contacts_{:04d}.vtp", n), 1);
  }
  pvd.write();
  s.schedules.snapshots.advance();
}

void ShearCell::write_series(const std::filesystem::path& out) const {
  std::string csv = flow_csv_header();
  for (const FlowRow& r : state_.measurements.rows) csv += flow_csv_row(r, config_.cell()->size[2]);
  write_file_atomically(out / "timeseries.csv", csv);
}

nlohmann::json ShearCell::write_results(const std::filesystem::path& out,
                                        const RunCost& cost) const {
  write_series(out);
  const CellMeasurements& m = state_.measurements;
  write_file_atomically(out / "velocity_profile.csv", m.profile.csv());
  write_file_atomically(out / "sommerfeld_hist.csv", sommerfeld_histogram_csv(m.histogram));
  write_file_atomically(out / "contacts.csv",
                        contacts_csv(state_.world.bodies, stepper_.contacts(), state_.dt));
  nlohmann::json summary = cell_summary(config_, units_, state_, cost);
  write_file_atomically(out / "summary.json", summary.dump(2) + "\n");
  return summary;
}

std::string ShearCell::progress_line(double elapsed) const {
  const ShearCellState& s = state_;
  const std::vector<FlowRow>& rows = s.measurements.rows;
  // The drive's speed over the current output interval, else the last row's.
  const double gdot =
      shear_rate(s.measurements.recent_speed(s.drive_speed()), config_.cell()->size[2]);
  const double done = s.strain / config_.run.strain;
  const double left = done > 0.0 ? elapsed * (1.0 - done) / done : 0.0;
  // Whether the averages can be trusted yet (measure/steadiness.hpp).
  std::string state;
  if (s.strain <= config_.run.transient_strain) {
    state = "transient";
  } else if (const Drift d = wall_speed_drift(rows, config_.run.transient_strain);
             d.known && !d.steady) {
    state = fmt::format("not yet steady: wall speed {:+.0f}% +- {:.0f}%", 100.0 * d.change,
                        100.0 * d.error);
  }
  // The stress: applied, or under rate control the last row's measured one.
  const bool rate = config_.cell()->control != ShearControl::Stress;
  const double tau = !rate          ? config_.cell()->shear_stress
                     : rows.empty() ? 0.0
                                    : invariants(rows.back().stress).shear;
  return fmt::format("strain {:6.2f}/{:.2f}  gamma_dot {:9.3g}  eta {:9.3g}  left {:5.0f} s  {}",
                     s.strain, config_.run.strain, gdot / units_.rate_unit,
                     relative_viscosity(tau, gdot, units_.eta_f), left, state);
}

}  // namespace dilatant
