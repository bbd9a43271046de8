#pragma once
// `dilatant analyze --model wyart-cates`: the Wyart–Cates fit
// (wyart_cates_fit.hpp) of every sample of an analysis input, the DST
// boundary each fit implies (wyart_cates_model.hpp), and the files:
//
//   wyart_cates.json        per sample phi_0, phi_m, sigma_star, A, alpha,
//     beta with errors (null: held fixed) and `*_source` (fixed or fitted),
//     chi2_per_dof, the weights, the fitted points and stress range, the
//     correlation matrix, and `dst`: phi_dst with its error (propagated from
//     the covariance), the onset stress there, and the regimes' bounds; or a
//     `fit_note` saying why there is no fit. Units, settings, version, input.
//   wyart_cates_curves.csv  sample,phi,kind,shear_stress,shear_rate,viscosity,fitted:
//     kind `data` (every point; fitted true/false) and `model` (the fitted
//     model at the curve's phi), what the overlay plot draws;
//   wyart_cates_map.csv     sample,phi,regime,turn_low,turn_high,shear_jamming_stress:
//     the flow-state map the fit implies, phi from below phi_DST to phi_0
//     (empty: no such stress), what the map plot draws.
//
// Samples that differ only by their seed (a sweep over cell.seed;
// wyart_cates_seeds.hpp) are fitted one by one and then pooled: one more
// sample, labelled without the seed, fitted on all their curves, whose JSON
// entry has a `seeds` block (members, and the mean, sd and standard error of
// each parameter and of phi_DST over the per-seed fits).
//
// The `dst` block and the map are in the data's stress units.
#include <filesystem>
#include <string>
#include <vector>

#include "analysis/analysis_input.hpp"
#include "analysis/wyart_cates_fit.hpp"
#include "analysis/wyart_cates_seeds.hpp"

namespace dilatant::analysis {

struct WyartCatesSample {
  std::string sample;
  std::size_t curves = 0;
  WyartCatesOutcome outcome;
  DstOnset onset;              // of the fitted model; NaN without a fit
  double onset_phi_err = 0.0;  // phi_DST's standard error
  // A pooled sample: the samples of its seeds, and the scatter of their own
  // fits (empty for a sample of the input).
  std::vector<std::string> members;
  std::vector<SeedSpread> seed_spreads;

  // Whether a curve labelled `curve_sample` is one of this sample's.
  bool holds(const std::string& curve_sample) const;
};

struct WyartCatesReport {
  std::string source;
  InputKind kind = InputKind::Manifest;
  UnitSystem units = UnitSystem::SI;
  WyartCatesSettings settings;
  std::vector<FlowCurve> curves;  // as read, for the overlay
  std::vector<WyartCatesSample> samples;

  bool any_fit() const;
};

// Fits each sample of `input`, in the input's order of samples, then each
// group of seeds pooled (after them, in the order of their first member).
WyartCatesReport wyart_cates_report(const AnalysisInput& input, const WyartCatesSettings& settings);

std::string wyart_cates_json(const WyartCatesReport& report);
std::string wyart_cates_curves_csv(const WyartCatesReport& report);
std::string wyart_cates_map_csv(const WyartCatesReport& report);

// The three files, into an existing folder.
void write_wyart_cates_files(const WyartCatesReport& report, const std::filesystem::path& dir);

// Removes the files above and their plots (wyart_cates.png, .svg) from `dir`:
// an analysis without the model does, so that an earlier fit is never drawn
// as this one's.
void remove_wyart_cates_files(const std::filesystem::path& dir);

}  // namespace dilatant::analysis
