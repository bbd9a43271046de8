#pragma once
// The shear cell's unit system (docs/model.md "Units"). Inside, code units:
// largest radius R, particle density rho_p and applied shear stress tau. The
// only free dynamical number is
//
//     lambda = sqrt(tau rho_p) R / eta_f     =>  eta_f = sqrt(tau rho_p) R / lambda,
//
// so the fluid viscosity is an input derived from lambda (it sets the friction
// law's Sommerfeld numbers), and results are reported in the paper's units
// (Fernandez et al. 2013, Fig. 2): shear rate in eta_f / (rho_p R^2), stress in
// eta_f^2 / (rho_p R^2), viscosity in eta_f. The formulas keep the symbols, so a
// cell with tau, rho_p or R other than 1 stays right.
//
// A force in the paper's units is a stress times R^2: eta_f^2 / rho_p. A
// material constant given in it (the critical load F* of the critical-load
// friction law) is one number however the stress applied varies, because
// eta_f, rho_p and R are the material's; in code units it becomes
// F*_paper eta_f^2 / rho_p = F*_paper tau R^2 / lambda^2, so a lambda sweep
// (tau_paper = lambda^2) moves the applied stress across sigma* = F* / R^2.
#include <cmath>

namespace dilatant {

struct CellUnits {
  double lambda = 0.0;
  double eta_f = 0.0;        // sqrt(tau rho_p) R / lambda
  double rate_unit = 0.0;    // eta_f / (rho_p R^2): the paper's unit of shear rate
  double stress_unit = 0.0;  // eta_f^2 / (rho_p R^2): the paper's unit of stress
  double force_unit = 0.0;   // eta_f^2 / rho_p: the paper's unit of force
};

inline CellUnits make_cell_units(double shear_stress, double density, double radius_max,
                                 double lambda) {
  CellUnits u;
  u.lambda = lambda;
  u.eta_f = std::sqrt(shear_stress * density) * radius_max / lambda;
  u.rate_unit = u.eta_f / (density * radius_max * radius_max);
  u.stress_unit = u.eta_f * u.eta_f / (density * radius_max * radius_max);
  u.force_unit = u.eta_f * u.eta_f / density;
  return u;
}

}  // namespace dilatant
