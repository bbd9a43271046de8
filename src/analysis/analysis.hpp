#pragma once
// The whole rheometer analysis (docs/analysis.md, paper Fig. 3):
//   1. each flow curve: plateau, onset, n with its interval, regime (curve_analysis.hpp);
//   2. each sample: n(phi) of its CST curves fitted with n - 1 = A x^-alpha,
//      phi_max given or fitted (divergence_fit.hpp); when phi_max is given, a
//      second fit with phi_max free checks that n diverges there;
//   3. all samples: the master-curve collapse, one A and alpha for all, each
//      sample at its own phi_max (given, or fitted jointly), and how well the
//      samples collapse (chi2 per degree of freedom, rms deviation in decades).
// Only CST curves enter the n(phi) fits: a newtonian curve has no exponent, a
// DST one has n = infinity or beyond the cap (it bounds phi_max from above:
// dst_phi_min), an unresolved one too few points.
#include <optional>
#include <string>
#include <vector>

#include "analysis/analysis_input.hpp"
#include "analysis/analysis_settings.hpp"
#include "analysis/curve_analysis.hpp"
#include "analysis/divergence_fit.hpp"

namespace dilatant::analysis {

struct SampleReport {
  std::string sample;
  std::optional<double> phi_max_given;
  std::size_t curves = 0;
  std::size_t cst_curves = 0;
  std::size_t dst_curves = 0;
  double dst_phi_min = kNotFound;  // lowest phi with DST, NaN if none
  PhiSeries series;                // the CST points of the n(phi) fit
  DivergenceOutcome fit;           // phi_max given (fixed) or fitted
  DivergenceOutcome free_fit;      // phi_max fitted although given: the check
  std::vector<std::string> notes;  // e.g. curves left out of the fit, and why
};

struct CollapseReport {
  std::vector<std::string> samples;   // those in the joint fit, in series order
  std::vector<std::string> left_out;  // "B: why"
  DivergenceOutcome fit;              // phi_max per entry of `samples`
};

struct AnalysisReport {
  AnalysisInput input;  // curves sorted by sample (first appearance), then phi
  AnalysisSettings settings;
  std::vector<CurveResult> curves;  // parallel to input.curves
  std::vector<SampleReport> samples;
  CollapseReport collapse;
};

AnalysisReport analyse(AnalysisInput input, const AnalysisSettings& settings);

}  // namespace dilatant::analysis
