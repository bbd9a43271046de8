#include "drivers/model_setup.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <thread>

namespace dilatant {

FrictionLaw make_friction_law(const FrictionConfig& f, double eta_f, double critical_load) {
  switch (f.law) {
    case FrictionLawKind::Coulomb:
      return CoulombLaw{.mu0 = f.mu0, .eta_f = eta_f};
    case FrictionLawKind::Stribeck:
      return StribeckLaw{.mu0 = f.mu0,
                         .s_c = f.s_c,
                         .s_lim = f.s_lim,
                         .eta_f = eta_f,
                         .viscous_beyond_s_lim = f.viscous_beyond_s_lim};
    case FrictionLawKind::CriticalLoad:
      return CriticalLoadLaw{.mu0 = f.mu0, .critical_load = critical_load, .eta_f = eta_f};
  }
  return CoulombLaw{.mu0 = f.mu0, .eta_f = eta_f};
}

std::unique_ptr<SuspendingFluid> make_fluid(const FluidConfig& f, double eta_f) {
  std::optional<StokesDrag> drag;
  std::optional<SqueezeFilm> film;
  if (f.drag == DragKind::Stokes) drag = StokesDrag{.eta_f = eta_f};
  if (f.lubrication == LubricationKind::Normal)
    film = SqueezeFilm{.eta_f = eta_f,
                       .cutoff = f.lubrication_cutoff,
                       .regularization = f.lubrication_regularization};
  // No viscosity, no fluid (a dry granular scene): nothing to add, and no
  // detection reach to widen.
  if ((!drag && !film) || eta_f <= 0.0) return nullptr;
  return std::make_unique<SuspendingFluid>(drag, film);
}

int hardware_threads() {
  return std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
}

std::string thread_cap_warning(const SolverConfig& s) {
  if (s.threads <= hardware_threads()) return "";
  return fmt::format(
      "dilatant: warning: solver.threads = {} is more than this machine's {} hardware threads; "
      "using {} (more threads than cores make every sweep wait; results do not depend on the "
      "count)",
      s.threads, hardware_threads(), hardware_threads());
}

std::string oversubscription_warning(int jobs, int threads_per_job) {
  const long asked = static_cast<long>(jobs) * threads_per_job;
  if (jobs <= 1 || asked <= hardware_threads()) return "";
  return fmt::format(
      "dilatant: warning: {} points side by side with {} solver thread{} each ask for {} threads "
      "on this machine's {}: every point runs slower than alone (lower --jobs or "
      "solver.threads; results do not depend on either)",
      jobs, threads_per_job, threads_per_job == 1 ? "" : "s", asked, hardware_threads());
}

SolverSettings make_solver_settings(const SolverConfig& s) {
  const int cores = hardware_threads();
  return SolverSettings{.convergence = s.convergence,
                        .tolerance = s.tolerance,
                        .max_iterations = s.max_iterations,
                        .freeze_branches_after = s.freeze_branches_after,
                        .threads = s.threads > 0 ? std::min(s.threads, cores) : cores,
                        .relaxation = s.relaxation,
                        .acceleration = s.acceleration,
                        .skip_open_contacts = s.skip_open_contacts,
                        .redo_unconverged = s.redo_unconverged};
}

double weight_force(const World& world) {
  double heaviest = 0.0;
  for (std::size_t i = 0; i < world.bodies.size(); ++i)
    heaviest = std::max(heaviest, world.bodies.mass(i));
  return heaviest * world.gravity.norm();
}

}  // namespace dilatant
