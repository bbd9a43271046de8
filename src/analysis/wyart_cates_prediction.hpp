#pragma once
// `dilatant predict --model wyart_cates.json --phi X [--stress S] [--sample NAME]`:
// the flow regime a Wyart–Cates fit (wyart_cates_report.hpp) implies at a
// volume fraction, and, at a stress, the state of the stress-controlled flow
// (wyart_cates_model.hpp): the answer from the suspension's own measured
// parameters instead of the built-in table of the paper's model
// (prediction_report.hpp). The answer names its source.
#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "analysis/divergence_fit.hpp"
#include "analysis/wyart_cates_model.hpp"

namespace dilatant::analysis {

// One sample's fit, read back from wyart_cates.json.
struct FittedWyartCates {
  std::string file;
  std::string sample;
  WyartCatesParameters model;
  Estimate phi_0, phi_m, phi_dst;  // err NaN when not known
  nlohmann::ordered_json units;    // as written by the fit
  // What the boundaries' errors are: the fit's, or for a pooled fit of seeds
  // the larger of the fit's and the seeds' standard error.
  std::string errors = "the fit's standard errors";
  // The volume fraction the fit was made in, and so the one --phi is read as:
  // "bulk" (a sweep's measured phi_bulk) or "nominal" (older files: nominal).
  std::string phi_basis = "nominal";
};

// The names of the fitted samples in a wyart_cates.json; InputError when the
// file is not one (named with the file and what is wrong).
std::vector<std::string> fitted_wyart_cates_samples(const std::filesystem::path& file);

// `sample` empty: the file's only fitted sample, or the pooled fit of a file
// that holds one suspension's seeds and their pooled fit (wyart_cates_seeds.hpp);
// InputError when there are several others (naming them, and the option to choose:
// `sample_option`), when the sample is not in the file or has no fit.
FittedWyartCates read_fitted_wyart_cates(const std::filesystem::path& file,
                                         const std::string& sample,
                                         const std::string& sample_option = "--sample");

// The regime at phi (cst, dst, shear_jamming, no_flow) with the boundaries
// and their errors, margin_sigma (the distance in standard errors to the
// nearest boundary; below 2 `uncertain`), the stresses of the S and of shear
// jamming at phi; with a stress: the state there (flows, turns_back, jammed),
// the viscosity, shear rate, f and phi_J. `source` says it is the fit's.
nlohmann::ordered_json wyart_cates_prediction(const FittedWyartCates& fit, double phi,
                                              std::optional<double> stress);

}  // namespace dilatant::analysis
