#include "measure/cell_measurements.hpp"

#include <algorithm>
#include <cmath>
#include <tuple>
#include <utility>

#include "boundary/lid_resistance.hpp"
#include "boundary/wall_forces.hpp"
#include "measure/particle_stress.hpp"

namespace dilatant {

StepStress CellMeasurements::accumulate(const StepSample& step,
                                        const MeasurementSettings& settings) {
  const std::vector<Contact>& contacts = step.contacts;
  const StepReport& report = step.report;
  const Drive& drive = step.drive;
  const double dt = step.dt;
  const bool steady = step.strain > settings.transient_strain;
  const ContactCounts n = count_contacts(step.world.bodies, contacts, dt, settings.s_lim,
                                         steady ? &histogram : nullptr);
  const WallForces f = drive.wall_forces(step.world, contacts, dt);
  IntervalSums& a = interval;
  a.time += dt;
  a.velocity += step.velocity * dt;
  a.kinetic_energy += report.kinetic_energy * dt;
  a.contacts += double(report.contacts_closed) * dt;
  // Contact fractions are time averages: with the adaptive step, a plain count
  // per step would over-weight the fast (short-step) phases of the flow.
  a.closed += n.closed * dt;
  a.boundary += n.boundary * dt;
  a.over_s_lim += n.over_s_lim * dt;
  a.impulsive += n.impulsive * dt;
  a.impulsive_boundary += n.impulsive_boundary * dt;
  a.bottom_force_x += f.bottom[0] * dt;
  a.top_force_z += f.top[2] * dt;
  a.bottom_force_z += f.bottom[2] * dt;
  a.sliding_bl += n.sliding_power_bl * dt;
  a.sliding_hd += n.sliding_power_hd * dt;
  a.work_normal += report.contact_work.normal;
  a.work_bl += report.contact_work.tangential_bl;
  a.work_hd += report.contact_work.tangential_hd;
  a.work_lubrication += report.contact_work.lubrication;
  a.work_drag += report.drag_work;
  a.iterations += report.solve.iterations;
  a.max_residual = std::max(a.max_residual, report.solve.residual);
  const ContactResidual& r = report.contact_residual;
  const auto body_ids = [&](const Contact& c) {  // a plane k as -(k+1), as contacts.csv
    const Bodies& b = step.world.bodies;
    return std::pair{
        double(b.id[static_cast<std::size_t>(c.i)]),
        c.with_plane() ? double(c.other) : double(b.id[static_cast<std::size_t>(c.other)])};
  };
  if (r.max() > a.contact_residual_max && r.worst_contact >= 0) {
    a.contact_residual_step = double(step.step);
    std::tie(a.contact_residual_body_i, a.contact_residual_body_j) =
        body_ids(contacts[static_cast<std::size_t>(r.worst_contact)]);
  }
  a.contact_residual_max = std::max(a.contact_residual_max, r.max());
  a.contact_residual_rms += std::hypot(r.normal_rms, r.tangential_rms);
  a.steps += 1.0;
  a.unconverged += report.solve.converged ? 0.0 : 1.0;
  if (report.max_overlap > a.max_overlap && report.max_overlap_contact >= 0) {
    a.max_overlap = report.max_overlap;
    a.max_overlap_step = double(step.step);
    std::tie(a.max_overlap_body_i, a.max_overlap_body_j) =
        body_ids(contacts[static_cast<std::size_t>(report.max_overlap_contact)]);
  }
  // Particle stress over the volume between the walls' centre planes, z = 0 to
  // Lz (measure/particle_stress.hpp: there its sigma_zx averages to tau), or
  // over the Lees–Edwards box; the mean flow is the one the drag also uses.
  const Tensor3 virial = contact_impulse_moment(contacts);
  const Tensor3 kinetic =
      velocity_fluctuation_moment(step.world.bodies, drive.mean_flow(step.world));
  const double volume = settings.volume;
  Tensor3 sigma;
  for (std::size_t k = 0; k < virial.size(); ++k) {
    a.stress_dt[k] -= (virial[k] + kinetic[k] * dt) / volume;
    sigma[k] = -(virial[k] + kinetic[k] * dt) / (volume * dt);
  }
  // On the walls, or without them the bulk's (Drive::normal_stress).
  a.normal_stress += drive.normal_stress(step.world, f, sigma[tensor_index(kZ, kZ)]) * dt;
  if (steady) profile.add(step.world, dt);
  // The films' resistance to the lid, for the pressure control's update (only
  // a Lees–Edwards box dilates).
  const double lid = step.world.box.lees_edwards
                         ? film_lid_resistance(contacts, volume, step.world.box.length[2], dt)
                         : 0.0;
  return {.sigma_zx = sigma[tensor_index(kZ, kX)],
          .sigma_zz = sigma[tensor_index(kZ, kZ)],
          .lid_resistance = lid};
}

void CellMeasurements::close_row(double time, double strain, double phi_bulk) {
  rows.push_back(interval.close(time, strain));
  rows.back().phi_bulk = phi_bulk;
  interval = IntervalSums{};
}

double CellMeasurements::recent_speed(double current) const {
  return interval.time > 0.0 ? interval.velocity / interval.time
         : rows.empty()      ? current
                             : rows.back().wall_velocity;
}

CellRecords CellMeasurements::records(double from, const ShearGeometry& geometry,
                                      const CellUnits& units, bool walls) const {
  return {.rheology = steady_rheology(rows, from, geometry, units),
          .stress = StressRecord::of(rows, from),
          .contacts = ContactRecord::of(rows, from),
          .energy = EnergyRecord::of(rows, from),
          .wall_forces = WallForceRecord::of(rows, from, walls),
          .solver = SolverRecord::of(rows)};
}

void CellMeasurements::restart_steady_averages() {
  std::fill(profile.sums().begin(), profile.sums().end(), 0.0);
  std::fill(profile.weights().begin(), profile.weights().end(), 0.0);
  histogram = SommerfeldHistogram{};
}

}  // namespace dilatant
