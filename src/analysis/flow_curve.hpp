#pragma once
// A flow curve as the analysis sees it: the points of one stress ramp (or of
// one simulated (phi, mu0) series), labelled with the sample and the volume
// fraction. Independent of the engine: rheometer files and simulation tables
// both end up here (docs/analysis.md).
//
// Units are those of the source, never mixed within one analysis:
//   rheometer files  stress Pa, rate 1/s, viscosity Pa s (converted on reading)
//   simulations      the paper's units: stress eta_f^2/(rho_p R^2),
//                    rate eta_f/(rho_p R^2), viscosity eta_f
#include <cstddef>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace dilatant::analysis {

enum class UnitSystem { SI, Paper };

struct FlowPoint {
  double shear_stress = 0.0;
  double shear_rate = 0.0;      // 0 for a jammed simulation point
  double viscosity = 0.0;       // NaN for a jammed simulation point
  double shear_rate_err = 0.0;  // one standard error; 0 = not known (rheometer data)
  bool valid = true;            // false: outside the model's validity; drawn, never fitted
  bool jammed = false;          // the simulated cell stopped: evidence of DST
  std::size_t line = 0;         // line in the source file, for messages
  // The suspension's own volume fraction at this point, where the source
  // measured one (a sweep's phi_bulk: a wall cell's bulk dilates away from the
  // nominal phi, a Lees–Edwards box's realised radii shift it slightly); NaN
  // where only the curve's nominal phi is known (rheometer data).
  double phi_measured = std::numeric_limits<double>::quiet_NaN();
  // One standard error of the viscosity where the source measured it apart
  // from the rate's (a rate-controlled sweep point: the rate is imposed, its
  // error 0, and the viscosity's comes from the stress, eta_err); 0 = not known.
  double viscosity_err = 0.0;
  // The fraction of boundary-lubricated contacts where the source counted it
  // (a sweep's frac_bl); NaN otherwise. Locates where the contacts leave the
  // hydrodynamic branch (contact_onset.hpp).
  double frac_bl = std::numeric_limits<double>::quiet_NaN();
};

// A fit window chosen by the user, in stress units of the curve.
struct StressWindow {
  double low = 0.0;
  double high = 0.0;
  std::string origin;  // where it was set, e.g. "manifest.toml:7: curve[2].window_stress"
};

struct FlowCurve {
  std::string source;  // the file the points come from
  std::string step;    // the file's step ("2 'Flow Curve Up'"); "" for a file of one step
  std::string sample;  // coating (rheometer) or "mu0=<value>" (simulation)
  double phi = 0.0;
  std::optional<StressWindow> window;
  std::vector<FlowPoint> points;  // ascending shear stress
  std::size_t dropped_rows = 0;   // rows left out (io/table_rows.hpp, rule 2)
};

}  // namespace dilatant::analysis
