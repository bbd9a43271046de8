// Where the contacts leave the hydrodynamic branch (analysis/contact_onset.hpp):
// the crossing of frac_bl's minimum + kFracBlRise, interpolated in closed form;
// a rise before the minimum, jammed points and curves without frac_bl give
// none; a sweep table's frac_bl reaches it through `dilatant analyze`; and the
// onsets `dilatant predict` ships are this rule on their committed curves.
#include "analysis/contact_onset.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "analysis/analysis_input.hpp"
#include "analysis/curve_analysis.hpp"
#include "analysis/onset_table.hpp"
#include "io/input_error.hpp"
#include "io/io_test_files.hpp"

namespace dilatant::analysis::contact_onset_test {
namespace {

FlowCurve curve(const std::vector<std::vector<double>>& stress_rate_frac_bl) {
  FlowCurve c;
  for (const auto& v : stress_rate_frac_bl) {
    FlowPoint p;
    p.shear_stress = v[0];
    p.shear_rate = v[1];
    p.viscosity = v[1] > 0.0 ? v[0] / v[1] : NAN;
    p.jammed = v[1] == 0.0;
    p.frac_bl = v[2];
    c.points.push_back(p);
  }
  return c;
}

TEST(ContactOnset, IsTheCrossingAboveTheMinimumInterpolatedInLog) {
  // frac_bl falls to 0.10 at stress 100 and is 0.10 + 2 rise at 1000: the
  // crossing is half way in frac_bl, at stress 10^2.5, rate sqrt(1 x 4).
  const double rise = kFracBlRise;
  const auto onset = contact_onset(curve({{1000.0, 4.0, 0.10 + 2 * rise},
                                          {1.0, 0.01, 0.30},
                                          {10.0, 0.1, 0.20},
                                          {100.0, 1.0, 0.10},
                                          {1e4, 0.0, 0.0}}));  // jammed: skipped
  ASSERT_TRUE(onset);
  EXPECT_NEAR(onset->stress, std::pow(10.0, 2.5), 1e-10);
  EXPECT_NEAR(onset->rate, 2.0, 1e-13);
  EXPECT_DOUBLE_EQ(onset->frac_bl_min, 0.10);
}

TEST(ContactOnset, ARiseBeforeTheMinimumIsNotTheOnset) {
  // Contacts locking on the plateau raise frac_bl by more than the rise at low
  // stress; only the rise after the minimum (0.15 at stress 100) counts.
  const double rise = kFracBlRise;
  const auto onset = contact_onset(curve({{1.0, 0.01, 0.20},
                                          {10.0, 0.1, 0.20 + 2 * rise},
                                          {100.0, 1.0, 0.15},
                                          {1000.0, 2.0, 0.15 + rise / 2},
                                          {1e4, 3.0, 0.15 + 3 * rise}}));
  ASSERT_TRUE(onset);
  EXPECT_NEAR(std::log10(onset->stress), 3.0 + 0.5 / 2.5, 1e-12);
}

TEST(ContactOnset, NoneWithoutARiseOrWithoutFracBl) {
  EXPECT_FALSE(contact_onset(curve({{1.0, 0.01, 0.3}, {10.0, 0.1, 0.2}, {100.0, 1.0, 0.24}})));
  auto rheometer = curve({{1.0, 0.01, 0.3}, {10.0, 0.1, 0.2}, {100.0, 1.0, 0.9}});
  rheometer.points[1].frac_bl = NAN;  // a point that counted no contacts
  EXPECT_FALSE(contact_onset(rheometer));
  EXPECT_FALSE(contact_onset(FlowCurve{}));
}

// A sweep table's frac_bl is read per point; one outside [0, 1] is refused
// with its line, as every column of the table is (exit 2 in the CLI).
TEST(ContactOnset, SweepTableFracBlIsReadAndCheckedByLine) {
  test::TempDir dir;
  const std::string head = "phi,mu0,shear_stress,gamma_dot,valid,jammed,frac_bl\n";
  const auto good = dir.write("good.csv", head +
                                              "0.61,0.4,1,0.1,true,false,0.2\n"
                                              "0.61,0.4,10,1,true,false,0.1\n"
                                              "0.61,0.4,100,4,true,false,0.3\n");
  const AnalysisInput in = load_analysis_input(good);
  ASSERT_EQ(in.curves.size(), 1u);
  const auto onset = contact_onset(in.curves[0]);
  ASSERT_TRUE(onset);
  // 0.1 + rise crossed a quarter of the way from 0.1 to 0.3, in log stress.
  EXPECT_NEAR(std::log10(onset->stress), 1.0 + kFracBlRise / 0.2, 1e-12);
  const auto bad = dir.write("bad.csv", head +
                                            "0.61,0.4,1,0.1,true,false,0.2\n"
                                            "0.61,0.4,10,1,true,false,1.5\n");
  try {
    load_analysis_input(bad);
    ADD_FAILURE() << "frac_bl 1.5 read";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("bad.csv:3: column 'frac_bl': 1.5 must be in [0, 1]"),
              std::string::npos)
        << e.what();
  }
}

// The shipped onsets (data/jamming/onsets.csv) are rule 8 on the decisive
// study's committed flow curves, read as `dilatant analyze` reads them: the
// boundary's neighbours, mu0 0.3 and 0.35, both seeds, to the table's 4 digits.
TEST(ContactOnset, ShippedOnsetsAreThisRuleOnTheirCurves) {
  const AnalysisInput in =
      load_analysis_input(std::filesystem::path(DILATANT_SOURCE_DIR) /
                          "docs/paper-reproduction/decisive-le-mu0/flowcurves.csv");
  const auto table = OnsetTable::builtin();
  int matched = 0;
  for (const auto& c : in.curves) {
    const CurveResult r = analyse_curve(c, AnalysisSettings{});
    ASSERT_FALSE(std::isnan(r.contact_onset_rate)) << c.sample;
    for (const auto& o : table.onsets()) {
      if (c.sample != fmt::format("mu0={:g} seed={}", o.mu0, o.seed)) continue;
      EXPECT_NEAR(r.contact_onset_rate / o.onset_rate, 1.0, 5e-4) << c.sample;
      ++matched;
    }
  }
  EXPECT_EQ(matched, 4);
}

}  // namespace
}  // namespace dilatant::analysis::contact_onset_test
