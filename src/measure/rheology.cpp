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
  r.viscosity = relative_viscosity(cell.shear_stress, r.shear_rate, units.eta_f);
  r.viscosity_err = r.viscosity * r.relative_error;
  const double p = r.normal_stress.mean;
  if (p > 0.0) {
    r.inertial_number = r.shear_rate * cell.radius * std::sqrt(cell.density / p);
    r.viscous_number = units.eta_f * r.shear_rate / p;
  }
  return r;
}

}  // namespace dilatant
