#pragma once
// Where the contacts of a simulated flow curve leave the hydrodynamic branch:
// the paper's onset (Fernandez et al. 2013, p. 2: a contact goes boundary
// lubricated once its Sommerfeld number falls below s_c, which in the
// Bagnold regime happens above gamma_dot_c ~ eta_f I_c^2/(s_c rho_p R^2)).
//
// On the hydrodynamic branch the fraction of boundary-lubricated contacts
// frac_bl falls as the stress rises; past the onset it rises for good. So,
// along the curve in order of stress, the onset is where frac_bl first
// exceeds its minimum over the flowing points by kFracBlRise, after that
// minimum; the stress is interpolated in log between the two points around the
// crossing (linearly in frac_bl), the rate in log-log at that stress. This is
// not rule 3's onset (the viscosity's first rise, curve_analysis.hpp): at
// phi_bulk 0.61 that rise is inertial, comes while frac_bl still falls and
// does not move with s_c (docs/jamming.md "The onset scale").
//
// Needs the points' frac_bl (a sweep's flowcurves.csv); rheometer data have
// none and get no such onset.
#include <optional>

#include "analysis/flow_curve.hpp"

namespace dilatant::analysis {

// More than the largest difference between two seeds' frac_bl at one point
// of the decisive study's Lees-Edwards ramps (0.042: mu0 0.4 at lambda 0.1,
// docs/jamming.md "The onset scale"), so that seed scatter alone makes no onset.
inline constexpr double kFracBlRise = 0.05;

struct ContactOnset {
  double stress = 0.0;       // in the curve's units
  double rate = 0.0;         // at that stress, log-log between the two points
  double frac_bl_min = 0.0;  // the bottom of the hydrodynamic branch
};

// Empty when a flowing point has no frac_bl, or frac_bl never rises by `rise`
// past its minimum (the curve ends or jams first). Jammed points are skipped.
std::optional<ContactOnset> contact_onset(const FlowCurve& curve, double rise = kFracBlRise);

}  // namespace dilatant::analysis
