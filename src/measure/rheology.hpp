#pragma once
// The cell's rheology, from the motion of its driven wall and the forces on its
// walls (docs/shear-cell.md "summary.json"):
//
//     gamma_dot = V / Lz                         (the paper's shear rate)
//     eta       = tau / gamma_dot                (apparent viscosity, here in eta_f)
//     P         = normal force on the walls / (Lx Ly)
//     I         = gamma_dot R sqrt(rho_p / P)    (inertial number)
//     J         = eta_f gamma_dot / P            (viscous number)
//
// Error bars are the block errors of the steady averages (measure/flow_series.hpp):
// the relative error of eta is that of V (tau is imposed exactly).
#include <vector>

#include "measure/cell_units.hpp"
#include "measure/flow_series.hpp"

namespace dilatant {

// What sets the numbers: the cell's height and the stress applied to it.
struct ShearGeometry {
  double height = 0.0;        // Lz, code units
  double shear_stress = 0.0;  // tau, code units
  double radius = 0.0;        // R (the largest radius), for I
  double density = 0.0;       // rho_p, for I
};

// Steady-state rheology, in code units except the viscosity (in eta_f).
struct Rheology {
  SteadyAverage wall_velocity;  // V
  double shear_rate = 0.0;      // V / Lz
  double shear_rate_err = 0.0;
  double relative_error = 0.0;  // of V, gamma_dot and eta alike; 0 if the cell does not move
  double viscosity = 0.0;       // tau / gamma_dot / eta_f; 0 if the cell does not move
  double viscosity_err = 0.0;
  SteadyAverage normal_stress;   // P
  double inertial_number = 0.0;  // 0 without a normal stress
  double viscous_number = 0.0;
};

// The shear rate of a wall moving at `wall_velocity` over a cell of `height`.
inline double shear_rate(double wall_velocity, double height) { return wall_velocity / height; }

// tau / gamma_dot in units of eta_f; 0 when the cell does not shear.
inline double relative_viscosity(double shear_stress, double rate, double eta_f) {
  return rate > 0.0 ? shear_stress / rate / eta_f : 0.0;
}

// Averages over the rows past `from` (strain).
Rheology steady_rheology(const std::vector<FlowRow>& rows, double from, const ShearGeometry& cell,
                         const CellUnits& units);

}  // namespace dilatant
