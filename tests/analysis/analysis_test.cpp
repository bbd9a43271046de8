// The whole analysis on the shipped example (examples/analysis: synthetic curves
// of the paper's four samples, 2% noise, a half-decade crossover; truth.json
// holds the values they were generated with), and the files it writes.
#include "analysis/analysis.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>

#include "analysis/report_files.hpp"
#include "io/io_test_files.hpp"

namespace dilatant::analysis::analysis_test {
namespace {

const std::filesystem::path kExample =
    std::filesystem::path(DILATANT_SOURCE_DIR) / "examples/analysis";

nlohmann::json truth() {
  std::ifstream in(kExample / "truth.json");
  return nlohmann::json::parse(in);
}

const AnalysisReport& example_report() {
  static const AnalysisReport report =
      analyse(load_analysis_input(kExample / "manifest.toml"), AnalysisSettings{});
  return report;
}

TEST(Analysis, ExampleCurvesGiveBackTheirRegimeViscosityAndExponent) {
  const AnalysisReport& r = example_report();
  const nlohmann::json t = truth();
  ASSERT_EQ(r.curves.size(), t["curves"].size());
  std::vector<double> n_errors;
  for (const auto& expected : t["curves"]) {
    const auto it = std::find_if(r.input.curves.begin(), r.input.curves.end(), [&](const auto& c) {
      return c.sample == expected["sample"] && c.phi == expected["phi"].get<double>();
    });
    ASSERT_NE(it, r.input.curves.end()) << expected;
    const CurveResult& got = r.curves[static_cast<std::size_t>(it - r.input.curves.begin())];
    const std::string where = expected["file"];
    EXPECT_EQ(regime_name(got.regime), expected["regime"].get<std::string>()) << where;
    // A median over ~25 plateau points with 2% noise (curve_analysis_test: < 3%).
    EXPECT_NEAR(got.eta_newtonian / expected["eta_newtonian"].get<double>(), 1.0, 0.03) << where;
    // With a half-decade crossover the 10% threshold is crossed where eta rises
    // slowly, so 2% noise moves the onset by up to ~35% (curve_analysis_test).
    EXPECT_NEAR(got.onset_stress / expected["onset_stress"].get<double>(), 1.0, 0.4) << where;
    if (expected["regime"] == "cst") {
      const double n = expected["n"];
      n_errors.push_back(got.n / n - 1.0);
      EXPECT_LT(std::abs(got.n / n - 1.0), 0.15) << where << ": n " << got.n << " vs " << n;
    } else {
      EXPECT_EQ(got.dst_evidence, DstEvidence::RateNotIncreasing) << where;
    }
  }
  // The documented bias of the window at this crossover: median -2% to -4%.
  std::sort(n_errors.begin(), n_errors.end());
  EXPECT_GT(n_errors[n_errors.size() / 2], -0.06);
  EXPECT_LT(n_errors[n_errors.size() / 2], 0.01);
}

TEST(Analysis, ExampleSamplesGiveBackPhiMaxAndTheMasterCurve) {
  const AnalysisReport& r = example_report();
  const nlohmann::json t = truth();
  ASSERT_EQ(r.samples.size(), 4u);
  for (const SampleReport& s : r.samples) {
    const double phi_max = t["samples"][s.sample]["phi_max"];
    EXPECT_EQ(s.cst_curves, 6u) << s.sample;
    EXPECT_EQ(s.dst_curves, 1u) << s.sample;
    EXPECT_GT(s.dst_phi_min, phi_max) << "DST only above phi_max";
    ASSERT_TRUE(s.fit.fit) << s.sample << ": " << s.fit.why_not;
    // Fitted (C, D) or, for the given ones (A, B), fitted again as a check.
    const DivergenceFit& free = s.phi_max_given ? *s.free_fit.fit : *s.fit.fit;
    const Estimate pm = free.phi_max[0];
    EXPECT_NEAR(pm.value, phi_max, 3 * pm.err) << s.sample;
    EXPECT_NEAR(pm.value, phi_max, 0.005) << s.sample << ": about a tenth of the phi range";
  }
  ASSERT_TRUE(r.collapse.fit.fit) << r.collapse.fit.why_not;
  const DivergenceFit& c = *r.collapse.fit.fit;
  const double A = t["A"], alpha = t["alpha"];
  // The exponents come out 2-4% low (the window's bias), which lowers A by as
  // much and alpha a little: 3 standard errors plus that bias.
  EXPECT_NEAR(c.A.value, A, 3 * c.A.err + 0.05 * A);
  EXPECT_NEAR(c.alpha.value, alpha, 3 * c.alpha.err + 0.03);
  EXPECT_EQ(c.points, 24u);
}

TEST(Analysis, TheCollapseQualityTellsTheRightPhiMaxFromAWrongOne) {
  const AnalysisReport& right = example_report();
  // Every sample at polymer A's phi_max, as if the coating did not matter.
  AnalysisInput wrong_input = load_analysis_input(kExample / "manifest.toml");
  for (const auto& s : wrong_input.samples) wrong_input.phi_max[s] = 0.578;
  const AnalysisReport wrong = analyse(wrong_input, AnalysisSettings{});
  ASSERT_TRUE(right.collapse.fit.fit);
  ASSERT_TRUE(wrong.collapse.fit.fit);
  // Right: residuals a little beyond the error bars (the window's bias), chi2/dof ~2.
  EXPECT_LT(right.collapse.fit.fit->chi2_per_dof(), 4.0);
  EXPECT_GT(wrong.collapse.fit.fit->chi2_per_dof(), 5 * right.collapse.fit.fit->chi2_per_dof());
  EXPECT_GT(wrong.collapse.fit.fit->rms_log10_deviation,
            2 * right.collapse.fit.fit->rms_log10_deviation);
}

std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string l; std::getline(in, l);) out.push_back(l);
  return out;
}

TEST(ReportFiles, WriteOneRowPerCurveAndPointAndTheFitsAsJson) {
  const AnalysisReport& r = example_report();
  test::TempDir dir;
  write_report_files(r, dir.path() / "out");
  std::ifstream curves_file(dir.path() / "out/curves.csv");
  std::stringstream curves_text;
  curves_text << curves_file.rdbuf();
  const auto curves = lines(curves_text.str());
  ASSERT_EQ(curves.size(), 1 + r.curves.size());
  EXPECT_EQ(
      curves[0].rfind("sample,phi,eta_newtonian,onset_stress,onset_rate,n,n_low,n_high,regime,", 0),
      0u)
      << curves[0];
  const auto dst = std::find_if(curves.begin(), curves.end(),
                                [](const auto& l) { return l.find(",dst,") != std::string::npos; });
  ASSERT_NE(dst, curves.end());
  EXPECT_NE(dst->find(",inf,inf,inf,dst,rate_not_increasing,"), std::string::npos) << *dst;
  EXPECT_EQ(lines(points_csv(r)).size(), 1 + 28u * 49u);

  std::ifstream fits_file(dir.path() / "out/fits.json");
  const nlohmann::json fits = nlohmann::json::parse(fits_file);
  EXPECT_EQ(fits["units"]["viscosity"], "Pa s");
  for (const char* s : {"A", "B", "C", "D"}) {
    const auto& sample = fits["samples"][s];
    for (const char* key : {"phi_max", "A", "A_err", "alpha", "alpha_err", "chi2_per_dof"})
      EXPECT_TRUE(sample[key].is_number()) << s << "." << key;
  }
  EXPECT_EQ(fits["samples"]["A"]["phi_max_source"], "given");
  EXPECT_TRUE(fits["samples"]["A"]["phi_max_err"].is_null());
  EXPECT_EQ(fits["samples"]["C"]["phi_max_source"], "fitted");
  EXPECT_TRUE(fits["samples"]["C"]["phi_max_err"].is_number());
  EXPECT_TRUE(fits["samples"]["A"]["free_fit"]["phi_max"].is_number());
  for (const char* key : {"A", "alpha", "chi2_per_dof", "rms_log10_deviation"})
    EXPECT_TRUE(fits["collapse"][key].is_number()) << key;
  EXPECT_EQ(fits["collapse"]["phi_max"]["D"]["source"], "fitted");
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "out/fits.json.part"));
}

}  // namespace
}  // namespace dilatant::analysis::analysis_test
