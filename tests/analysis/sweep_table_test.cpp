// A simulation sweep's flowcurves.csv: grouping into curves per (phi, mu0),
// invalid rows drawn but not fitted, jammed rows as DST evidence, and errors.
//
// tests/analysis/data/flowcurves.csv is a small hand-made sweep in the paper's
// units: curves (phi, mu0) = (0.55, 0.1), (0.58, 0.1), (0.55, 0.4) generated with
// n = 1, 2, 1.5 above a sharp onset, eta_N = 40, 80, 40 and 2% rate noise (the
// rows' gamma_dot_err); their lambda = 1 rows are marked valid = false and carry a
// rate 1.8 x too high; (0.58, 0.4) jams from lambda 8 on. One row is out of order.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "analysis/analysis_input.hpp"
#include "analysis/curve_analysis.hpp"
#include "io/io_test_files.hpp"

namespace dilatant::analysis::sweep_table_test {
namespace {

const std::filesystem::path kSweep =
    std::filesystem::path(DILATANT_SOURCE_DIR) / "tests/analysis/data/flowcurves.csv";

TEST(SweepTable, GroupsRowsIntoOneCurvePerPhiAndMu0) {
  const AnalysisInput in = load_analysis_input(kSweep);
  EXPECT_EQ(in.kind, InputKind::SweepTable);
  EXPECT_EQ(in.units, UnitSystem::Paper);
  EXPECT_EQ(in.samples, (std::vector<std::string>{"mu0=0.1", "mu0=0.4"}));
  ASSERT_EQ(in.curves.size(), 4u);
  for (const auto& c : in.curves) {
    ASSERT_EQ(c.points.size(), 7u) << c.sample << " phi " << c.phi;
    for (std::size_t k = 1; k < c.points.size(); ++k)
      EXPECT_LT(c.points[k - 1].shear_stress, c.points[k].shear_stress) << "sorted by stress";
    EXPECT_FALSE(c.points.front().valid) << "the lambda = 1 row is outside the model's validity";
  }
  const FlowCurve& jamming = in.curves[3];
  EXPECT_EQ(jamming.sample, "mu0=0.4");
  EXPECT_EQ(jamming.phi, 0.58);
  EXPECT_TRUE(jamming.points.back().jammed);
  EXPECT_EQ(jamming.points.back().shear_rate, 0.0);
  EXPECT_TRUE(std::isnan(jamming.points.back().viscosity));
  EXPECT_DOUBLE_EQ(in.curves[0].points[1].shear_rate_err, 0.0019);
}

TEST(SweepTable, GivesNPerPhiAndMu0AndTreatsJammingAsDst) {
  const AnalysisInput in = load_analysis_input(kSweep);
  const double generated_n[] = {1.0, 2.0, 1.5};
  const double generated_eta[] = {40.0, 80.0, 40.0};
  for (int k = 0; k < 3; ++k) {
    const CurveResult r = analyse_curve(in.curves[k], AnalysisSettings{});
    EXPECT_EQ(r.regime, Regime::Cst) << k;
    // The 95% interval holds the generating exponent.
    EXPECT_LE(r.n_low, generated_n[k]) << k;
    EXPECT_GE(r.n_high, generated_n[k]) << k;
    // Two or three plateau points with 2% noise: within 5%. Were the invalid
    // row used, the plateau would sit near 22.6 or 45 instead.
    EXPECT_NEAR(r.eta_newtonian / generated_eta[k], 1.0, 0.05) << k;
    EXPECT_FALSE(r.in_window.front());
    EXPECT_NEAR(r.noise, 0.02, 0.002) << "the rows' error bars";
  }
  const CurveResult jammed = analyse_curve(in.curves[3], AnalysisSettings{});
  EXPECT_EQ(jammed.regime, Regime::Dst);
  EXPECT_EQ(jammed.dst_evidence, DstEvidence::Jammed);
}

// Rows with a missing, zero or negative stress or rate are dropped and
// counted (io/table_rows.hpp); a jammed row's rate 0 is a result and is kept.
TEST(SweepTable, DropsRowsWithoutAPositiveStressOrRateAndCountsThem) {
  test::TempDir dir;
  const auto file =
      dir.write("flowcurves.csv",
                "phi,mu0,shear_stress,gamma_dot,gamma_dot_err,eta,valid,jammed\n"
                "0.5,0.1,1,1,0,1,true,false\n0.5,0.1,0,1,0,,true,false\n0.5,0.1,2,,0,,true,false\n"
                "0.5,0.1,4,-1,0,,true,false\n0.5,0.1,8,0,0,,true,true\n");
  const AnalysisInput in = read_sweep_table(file);
  ASSERT_EQ(in.curves.size(), 1u);
  EXPECT_EQ(in.curves[0].points.size(), 2u);
  EXPECT_EQ(in.dropped_rows, 3u);
  ASSERT_EQ(in.dropped.size(), 1u);
  EXPECT_EQ(in.dropped[0], file.string() +
                               ": 3 rows dropped (missing value: line 4; zero or negative "
                               "value: lines 3, 5)");
}

// A pressure-imposed point (control = pressure) measures phi instead of
// fixing it: it is left out of the flow curves at fixed phi; the others stay.
TEST(SweepTable, LeavesPressureControlledRowsOut) {
  test::TempDir dir;
  const auto file = dir.write("flowcurves.csv",
                              "phi,mu0,shear_stress,gamma_dot,valid,jammed,control\n"
                              "0.5,0.1,1,1,true,false,rate\n0.5,0.1,2,1,true,false,pressure\n"
                              "0.5,0.1,4,3,true,false,stress\n0.5,0.1,8,1,true,false,pressure\n");
  const AnalysisInput in = read_sweep_table(file);
  ASSERT_EQ(in.curves.size(), 1u);
  EXPECT_EQ(in.curves[0].points.size(), 2u);
  EXPECT_EQ(in.dropped_rows, 0u);
}

struct BadSweep {
  std::string name;
  std::string text;
  int line;
  std::string problem;
};

// A sweep's phi_bulk (the fraction the point measured) is each point's
// phi_measured, its eta_err the viscosity_err; a table without them, or an
// empty field, leaves NaN and 0.
TEST(SweepTable, ReadsEachPointsMeasuredBulkFraction) {
  test::TempDir dir;
  const auto file = dir.write("flowcurves.csv",
                              "phi,mu0,shear_stress,gamma_dot,valid,jammed,phi_bulk,eta_err\n"
                              "0.62,0.1,1,0.02,true,false,0.6097,2.5\n"
                              "0.62,0.1,10,0.1,true,false,,\n"
                              "0.62,0.1,100,0,true,true,0.6121,\n");
  const AnalysisInput in = read_sweep_table(file);
  ASSERT_EQ(in.curves.size(), 1u);
  const auto& p = in.curves[0].points;
  ASSERT_EQ(p.size(), 3u);
  EXPECT_EQ(in.curves[0].phi, 0.62);
  EXPECT_DOUBLE_EQ(p[0].phi_measured, 0.6097);
  EXPECT_TRUE(std::isnan(p[1].phi_measured));
  EXPECT_DOUBLE_EQ(p[2].phi_measured, 0.6121);  // a jam has its packing's fraction
  EXPECT_DOUBLE_EQ(p[0].viscosity_err, 2.5);    // eta_err, where given
  EXPECT_EQ(p[1].viscosity_err, 0.0);
  EXPECT_TRUE(std::isnan(load_analysis_input(kSweep).curves[0].points[0].phi_measured));
}

constexpr const char* kHeader = "phi,mu0,shear_stress,gamma_dot,gamma_dot_err,eta,valid,jammed\n";

std::vector<BadSweep> bad_sweeps() {
  const std::string h = kHeader;
  return {
      {"MissingColumn", "phi,mu0,shear_stress,gamma_dot,valid\n0.5,0.1,1,1,true\n", 1,
       "missing column 'jammed'"},
      {"NoRows", h, 1, "no data rows"},
      // A zero rate of a flowing row drops it (io/table_rows.hpp): none is left.
      {"ZeroRateWithoutJamming", h + "0.5,0.1,1,0,0,,true,false\n", 1,
       "no point left: 1 row dropped (zero or negative value: line 2)"},
      {"BadBoolean", h + "0.5,0.1,1,1,0,1,yes,false\n", 2, "'yes' is not true or false"},
      {"TextInANumber", h + "0.5,0.1,1,1,0,1,true,false\n0.5,0.1,x,1,0,1,true,false\n", 3,
       "'x' is not a number"},
      {"RepeatedStress", h + "0.5,0.1,1,1,0,1,true,false\n0.5,0.1,1,2,0,1,true,false\n", 3,
       "repeats line 2"},
      {"WrongFieldCount", h + "0.5,0.1,1,1,0,1,true\n", 2, "7 fields, the header has 8"},
      {"PhiOutOfRange", h + "0.8,0.1,1,1,0,1,true,false\n", 2, "must be in (0, 0.74)"},
      {"OnlyPressureControlled",
       "phi,mu0,shear_stress,gamma_dot,valid,jammed,control\n0.58,0.4,0.3,0.1,true,false,"
       "pressure\n0.58,0.4,0.5,0.1,true,false,pressure\n",
       1, "no flow curve: the 2 finished points are pressure-controlled"},
      {"PhiBulkOutOfRange",
       "phi,mu0,shear_stress,gamma_dot,valid,jammed,phi_bulk\n0.5,0.1,1,1,true,false,0.9\n", 2,
       "column 'phi_bulk': 0.9 must be in (0, 0.74)"},
      {"PhiBulkNotANumber",
       "phi,mu0,shear_stress,gamma_dot,valid,jammed,phi_bulk\n0.5,0.1,1,1,true,false,x\n", 2,
       "column 'phi_bulk': 'x' is not a number"},
      {"NegativeEtaErr",
       "phi,mu0,shear_stress,gamma_dot,valid,jammed,eta_err\n0.5,0.1,1,1,true,false,-2\n", 2,
       "column 'eta_err': -2 must be >= 0"},
      {"NaN", h + "0.5,0.1,nan,1,0,1,true,false\n", 1, "missing value: line 2"},
      {"Infinite", h + "0.5,0.1,inf,1,0,1,true,false\n", 2, "not a finite number"},
      // eta 2.50 where shear_stress / gamma_dot = 2.00: 25%, its digits allow 1.6%.
      {"EtaDisagrees", h + "0.5,0.1,1.00,0.500,0,2.50,true,false\n", 2,
       "eta 2.5 disagrees with shear_stress / gamma_dot = 2 by 25%"},
  };
}

class SweepTableBad : public ::testing::TestWithParam<BadSweep> {};

TEST_P(SweepTableBad, IsRefusedWithFileLineAndProblem) {
  const BadSweep& c = GetParam();
  test::TempDir dir;
  const auto file = dir.write("flowcurves.csv", c.text);
  const std::string message = test::input_error_message([&] { read_sweep_table(file); });
  EXPECT_EQ(message.rfind(file.string() + ":" + std::to_string(c.line) + ": ", 0), 0u) << message;
  EXPECT_NE(message.find(c.problem), std::string::npos) << message;
}

INSTANTIATE_TEST_SUITE_P(SweepTable, SweepTableBad, ::testing::ValuesIn(bad_sweeps()),
                         [](const auto& p) { return p.param.name; });

}  // namespace
}  // namespace dilatant::analysis::sweep_table_test
