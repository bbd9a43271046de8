#pragma once
// The onset of frictional thickening predicted from the paper's scaling
// (Fernandez et al. 2013, p. 2): in the Bagnold regime the local Sommerfeld
// number scales as s ~ eta_f I^2 / (gamma_dot rho_p R^2), so the flow can
// leave the hydrodynamic branch only above
//
//     gamma_dot_c ~ eta_f I_c^2 / (s_c rho_p R^2),
//
// with I_c the inertial number at the onset. The paper leaves the prefactor
// open; we measure it, with I_c, on our own flow curves
// (data/jamming/onsets.csv, python/dilatant/plots/onset_table.py, docs/jamming.md "The
// onset scale"): C = gamma_dot_c s_c rho_p R^2 / (eta_f I_c^2). The onset
// measured is where the fraction of boundary-lubricated contacts starts to
// rise for good, the paper's leaving of the hydrodynamic branch; not the
// viscosity's first rise, which at phi_bulk 0.61 is inertial and does not
// move with s_c. Rates are in eta_f/(rho_p R^2), the unit of our flow tables.
#include <filesystem>
#include <string>
#include <vector>

#include "analysis/numeric_csv.hpp"

namespace dilatant::analysis {

// One onset measured on a flow curve.
struct MeasuredOnset {
  double mu0 = 0.0;
  double phi_bulk = 0.0;
  double s_c = 0.0;
  double onset_rate = 0.0;       // gamma_dot where frac_bl starts to rise for good
  double inertial_number = 0.0;  // I at that rate
  int seed = 0;                  // the curve's seed (0: not given)
  std::string model;             // "literal", ...
  std::string source;            // where the flow curve is documented
};

// I_c^2 / s_c: the paper's onset scale with prefactor 1, in eta_f/(rho_p R^2).
inline double onset_rate_scale(double inertial_number, double s_c) {
  return inertial_number * inertial_number / s_c;
}

class OnsetTable {
 public:
  // Columns mu0, phi_bulk, s_c, onset_rate, inertial_number (all > 0 except
  // mu0 >= 0), model and source; throws InputError naming the line.
  static OnsetTable parse(const NumericCsv& csv);
  static OnsetTable builtin();  // data/jamming/onsets.csv of this version
  const std::vector<MeasuredOnset>& onsets() const { return onsets_; }

 private:
  std::vector<MeasuredOnset> onsets_;
};

// How far in phi from its measurement an onset is still given. I_c's
// dependence on phi is not measured (data/jamming/onsets.csv: phi_bulk 0.61
// only), so the measured I_c is used within the dense window where the literal
// model has a Newtonian branch at all (phi_bulk 0.59-0.61,
// docs/paper-reproduction.md) and nowhere else: at phi 0.3 it would be a guess
// (docs/jamming.md "The onset scale").
inline constexpr double kOnsetPhiReach = 0.02;

// Onsets of one mu0 whose phi_bulk differ by at most this are one state
// measured on several seeds (their packings' phi_bulk differ by 0.0002 in
// the Lees-Edwards box; 0.003 is the issue-34 tolerance for one bulk state).
inline constexpr double kOnsetSameState = 0.003;

struct OnsetPrediction {
  bool available = false;  // false when the table has no onset
  bool too_far = false;    // measured further than kOnsetPhiReach from the asked phi
  // The curves the prediction rests on: the measured friction nearest the
  // asked mu0, at the phi_bulk nearest the asked phi, every seed of it.
  std::vector<MeasuredOnset> measured;
  double prefactor = 0.0;                  // C: the geometric mean over the curves
  double inertial_number = 0.0;            // I_c: the geometric mean over the curves
  double scale = 0.0;                      // I_c^2 / s_c at the asked s_c
  double rate = 0.0;                       // C I_c^2 / s_c: the predicted onset rate
  double rate_low = 0.0, rate_high = 0.0;  // the curves' own C I_c^2/s_c at the asked s_c
  // Mean of the curves' phi_bulk and the mu0 they were measured at.
  double phi_bulk = 0.0, mu0 = 0.0;
};

// From the measured onsets nearest in mu0 (then in phi): I_c is taken as it
// was measured, so the prediction carries the paper's 1/s_c scaling and
// nothing else; how I_c moves with phi is not measured (docs/jamming.md).
OnsetPrediction predict_onset(const OnsetTable& table, double mu0, double phi, double s_c);

}  // namespace dilatant::analysis
