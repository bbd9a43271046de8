#pragma once
// The cell's rheology, from the motion of its drive and the forces on its
// walls or in its bulk (docs/shear-cell.md "summary.json"), the one place eta
// is computed, for either control:
//
//     gamma_dot = V / Lz                         (the paper's shear rate)
//     tau       = the applied stress (stress control), or the measured
//                 particle shear stress sigma_zx (rate control)
//     eta       = tau / gamma_dot                (apparent viscosity, here in eta_f)
//     P         = normal force on the walls / (Lx Ly), or the bulk's sigma_zz
//     I         = gamma_dot R sqrt(rho_p / P)    (inertial number)
//     J         = eta_f gamma_dot / P            (viscous number)
//
// Error bars are the block errors of the steady averages (measure/flow_series.hpp).
// Under stress control tau is exact and eta carries the relative error of V;
// under rate control V is exact and eta carries the error of the measured tau.
#include <nlohmann/json.hpp>
#include <vector>

#include "measure/cell_units.hpp"
#include "measure/flow_series.hpp"

namespace dilatant {

// What sets the numbers: the cell's height, its control and the stress applied to it.
struct ShearGeometry {
  double height = 0.0;           // Lz, code units
  double shear_stress = 0.0;     // tau applied, code units (stress control)
  bool rate_controlled = false;  // the rate is imposed and tau measured
  double radius = 0.0;           // R (the largest radius), for I
  double density = 0.0;          // rho_p, for I
};

// Steady-state rheology, in code units except the viscosity (in eta_f).
struct Rheology {
  SteadyAverage wall_velocity;  // V
  double shear_rate = 0.0;      // V / Lz
  double shear_rate_err = 0.0;
  double relative_error = 0.0;    // of V and gamma_dot alike; 0 if the cell does not move
  double shear_stress = 0.0;      // tau: applied, or measured under rate control
  double shear_stress_err = 0.0;  // 0 when applied
  double viscosity = 0.0;         // tau / gamma_dot / eta_f; 0 if the cell does not move
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

// Its keys of summary.json in the paper's units: shear_stress, gamma_dot(_err),
// eta(_err), wall_velocity(_err), normal_stress(_err), inertial_number,
// viscous_number. A jammed cell has gamma_dot 0 and no eta (null).
void write_rheology(nlohmann::json& summary, const Rheology& r, const CellUnits& units,
                    bool jammed);

}  // namespace dilatant
