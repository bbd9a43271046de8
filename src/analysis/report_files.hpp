#pragma once
// The result files of `dilatant analyze`, written atomically into one folder:
//
//   curves.csv  one row per flow curve:
//     sample,phi,eta_newtonian,onset_stress,onset_rate,n,n_low,n_high,regime,
//     dst_evidence,fall_stress,bagnold,n_sigma,consistency,window_stress_low,
//     window_stress_high,window_points,window,noise,points,file,step,dropped_rows
//     (empty = not applicable; n, n_low, n_high may be "inf"; regime is newtonian,
//     cst, dst, unresolved or jammed; fall_stress (where the rate fell, by rule
//     6's threshold) the stress of the point whose rate fell below the one
//     before it; bagnold (CST only) true when the interval of n holds 1; window
//     is auto or user; consistency is K of eta = K gamma_dot^n; noise the
//     relative rate noise used)
//   points.csv  one row per measured point, for the plots:
//     curve,sample,phi,shear_stress,shear_rate,viscosity,valid,jammed,in_window,
//     local_slope
//     (curve = 0-based row of curves.csv; local_slope = d ln eta / d ln gamma_dot,
//     empty for points not fitted, "inf" where the rate does not grow)
//   fits.json   per sample phi_max, A, alpha with uncertainties (and the free
//     phi_max check), the collapse with its quality, units, settings, version.
//
// Units: SI (Pa, 1/s, Pa s) for rheometer data, the paper's units for
// simulations; fits.json says which.
#include <filesystem>
#include <string>

#include "analysis/analysis.hpp"

namespace dilatant::analysis {

std::string curves_csv(const AnalysisReport& report);
std::string points_csv(const AnalysisReport& report);
std::string fits_json(const AnalysisReport& report);

// Creates `dir` if needed and writes the three files.
void write_report_files(const AnalysisReport& report, const std::filesystem::path& dir);

}  // namespace dilatant::analysis
