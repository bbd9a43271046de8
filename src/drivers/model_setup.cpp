#include "drivers/model_setup.hpp"

#include <algorithm>
#include <thread>

namespace dilatant {

FrictionLaw make_friction_law(const FrictionConfig& f, double eta_f) {
  switch (f.law) {
    case FrictionLawKind::Coulomb:
      return CoulombLaw{f.mu0, eta_f};
    case FrictionLawKind::Stribeck:
      return StribeckLaw{f.mu0, f.s_c, f.s_lim, eta_f};
  }
  return CoulombLaw{f.mu0, eta_f};
}

SolverSettings make_solver_settings(const SolverConfig& s) {
  const int cores = std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
  return SolverSettings{s.tolerance, s.max_iterations, s.freeze_branches_after,
                        s.threads > 0 ? s.threads : cores, s.relaxation};
}

}  // namespace dilatant
