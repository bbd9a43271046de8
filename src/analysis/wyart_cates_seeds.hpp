#pragma once
// Repeated packings of one suspension in a Wyart–Cates fit. A sweep over
// `cell.seed` labels its curves "mu0=0.5 seed=1", "mu0=0.5 seed=2", ...
// (sweep/flow_table.hpp, the `sample` column): the same suspension, independent
// packings. wyart_cates_report.hpp fits each seed alone and then all of them
// together (the pooled sample, labelled without the seed token); this file
// finds those groups and measures the scatter of the per-seed fits, the error
// bar that no single fit's covariance gives (a fit's errors come from its own
// residuals, which share one packing's structure).
#include <string>
#include <vector>

#include "analysis/divergence_fit.hpp"

namespace dilatant::analysis {

struct SeedGroup {
  std::string label;                 // the members' label without their seed token
  std::vector<std::string> members;  // in the input's order
};

// The groups of two or more samples whose labels are equal once their
// " seed=N" token is removed. A sample without that token belongs to none.
std::vector<SeedGroup> seed_groups(const std::vector<std::string>& samples);

// The spread of one fitted quantity over the seeds that were fitted: the mean,
// the sample standard deviation (n - 1) and the standard error of the mean
// sd / sqrt(n). With fewer than two values sd and sem are NaN.
struct SeedSpread {
  std::string name;  // phi_0, phi_m, sigma_star, A, alpha, beta, phi_dst
  std::size_t n = 0;
  double mean = 0.0, sd = 0.0, sem = 0.0;
};

SeedSpread seed_spread(std::string name, const std::vector<double>& values);

}  // namespace dilatant::analysis
