#include "measure/rheology.hpp"

#include <cmath>

namespace dilatant {

Rheology steady_rheology(const std::vector<FlowRow>& rows, double from, const ShearGeometry& cell,
                         const CellUnits& units) {
  Rheology r;
  r.wall_velocity =
      steady_average(rows, from, [](const FlowRow& row) { return row.wall_velocity; });
  r.normal_stress =
      steady_average(rows, from, [](const FlowRow& row) { return row.normal_stress; });
  const SteadyAverage& v = r.wall_velocity;
  r.shear_rate = shear_rate(v.mean, cell.height);
  r.shear_rate_err = v.error / cell.height;
  r.relative_error = r.shear_rate > 0.0 ? v.error / v.mean : 0.0;
  if (cell.rate_controlled) {
    // The stress is the particles' own (measure/particle_stress.hpp): with the
    // rate fixed, eta = <sigma_zx> / gamma_dot and its error that of <sigma_zx>.
    const SteadyAverage tau =
        steady_average(rows, from, [](const FlowRow& row) { return invariants(row.stress).shear; });
    r.shear_stress = tau.mean;
    r.shear_stress_err = tau.error;
    r.viscosity = relative_viscosity(tau.mean, r.shear_rate, units.eta_f);
    r.viscosity_err = relative_viscosity(tau.error, r.shear_rate, units.eta_f);
  } else {
    r.shear_stress = cell.shear_stress;
    r.viscosity = relative_viscosity(cell.shear_stress, r.shear_rate, units.eta_f);
    r.viscosity_err = r.viscosity * r.relative_error;
  }
  const double p = r.normal_stress.mean;
  if (p > 0.0) {
    r.inertial_number = r.shear_rate * cell.radius * std::sqrt(cell.density / p);
    r.viscous_number = units.eta_f * r.shear_rate / p;
  }
  return r;
}

void write_rheology(nlohmann::json& j, const Rheology& r, const CellUnits& u, bool jammed) {
  j["shear_stress"] = r.shear_stress / u.stress_unit;
  if (jammed) {
    j["gamma_dot"] = 0.0;
    j["gamma_dot_err"] = 0.0;
    j["eta"] = nullptr;
    j["eta_err"] = nullptr;
  } else {
    j["gamma_dot"] = r.shear_rate / u.rate_unit;
    j["gamma_dot_err"] = r.shear_rate_err / u.rate_unit;
    j["eta"] = r.viscosity;
    j["eta_err"] = r.viscosity_err;
  }
  j["wall_velocity"] = r.wall_velocity.mean;  // code units, sqrt(tau/rho_p)
  j["wall_velocity_err"] = r.wall_velocity.error;
  j["normal_stress"] = r.normal_stress.mean / u.stress_unit;
  j["normal_stress_err"] = r.normal_stress.error / u.stress_unit;
  j["inertial_number"] = r.inertial_number;
  j["viscous_number"] = r.viscous_number;
}

}  // namespace dilatant
