// The jamming table and the regime it predicts (analysis/jamming_table.hpp), on
// a hand-made table whose interpolation and boundaries are known exactly.
#include "analysis/jamming_table.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "io/input_error.hpp"

namespace dilatant::analysis::jamming_table_test {
namespace {

constexpr const char* kTable =
    "mu0,phi_max,phi_max_err,samples\n"
    "0,0.64,0.002,3\n"
    "0.5,0.58,0.004,3\n"
    "1,0.56,0.002,3\n";

TEST(JammingTable, InterpolatesLinearlyAndHoldsTheLastValue) {
  const auto t = JammingTable::parse(NumericCsv::from_text(kTable, "t.csv"));
  EXPECT_DOUBLE_EQ(t.phi_max_bl(0.0).value, 0.64);
  EXPECT_DOUBLE_EQ(t.phi_max_bl(0.25).value, 0.61);
  EXPECT_DOUBLE_EQ(t.phi_max_bl(0.25).error, 0.003);
  EXPECT_DOUBLE_EQ(t.phi_max_bl(0.75).value, 0.57);
  EXPECT_DOUBLE_EQ(t.phi_max_bl(3.0).value, 0.56);
  EXPECT_DOUBLE_EQ(t.phi_rcp().value, 0.64);
}

TEST(JammingTable, RegimesFollowThePapersBoundaries) {
  const auto t = JammingTable::parse(NumericCsv::from_text(kTable, "t.csv"));
  // mu0 0.5: CST up to 0.58, DST up to 0.64, no flow above.
  EXPECT_EQ(predict_regime(t, 0.5, 0.55).regime, FlowRegime::Cst);
  EXPECT_EQ(predict_regime(t, 0.5, 0.58).regime, FlowRegime::Cst);  // phi <= phi_max_BL
  EXPECT_EQ(predict_regime(t, 0.5, 0.60).regime, FlowRegime::Dst);
  EXPECT_EQ(predict_regime(t, 0.5, 0.64).regime, FlowRegime::Dst);  // phi <= phi_RCP
  EXPECT_EQ(predict_regime(t, 0.5, 0.645).regime, FlowRegime::NoFlow);
  // Frictionless spheres never thicken discontinuously: CST up to phi_RCP.
  EXPECT_EQ(predict_regime(t, 0.0, 0.63).regime, FlowRegime::Cst);
  // 0.55 is 0.03 = 7.5 sigma below 0.58: certain; 0.585 is 1.25 sigma above it.
  const auto far = predict_regime(t, 0.5, 0.55);
  EXPECT_NEAR(far.margin_sigma, 7.5, 1e-9);
  EXPECT_FALSE(far.uncertain);
  const auto near = predict_regime(t, 0.5, 0.585);
  EXPECT_NEAR(near.margin_sigma, 1.25, 1e-9);
  EXPECT_TRUE(near.uncertain);
}

TEST(JammingTable, BadTablesNameTheLine) {
  const auto message = [](const char* csv) {
    try {
      JammingTable::parse(NumericCsv::from_text(csv, "t.csv"));
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  using ::testing::HasSubstr;
  EXPECT_THAT(message("mu0,phi\n0,0.6\n"), HasSubstr("t.csv:1: no column phi_max"));
  EXPECT_THAT(message("mu0,phi_max,phi_max_err\n0.1,0.6,0\n"), HasSubstr("t.csv:2: mu0 = 0.1"));
  EXPECT_THAT(message("mu0,phi_max,phi_max_err\n0,0.64,0\n0,0.6,0\n"), HasSubstr("t.csv:3:"));
  EXPECT_THAT(message("mu0,phi_max,phi_max_err\n0,0.8,0\n"), HasSubstr("must be in (0, 0.74)"));
  EXPECT_THAT(message("mu0,phi_max,phi_max_err\n0,x,0\n"), HasSubstr("not a finite number"));
  EXPECT_THAT(message("mu0,phi_max,phi_max_err\n"), HasSubstr("no rows"));
}

TEST(JammingTable, TheBuiltInTableIsValid) {
  const auto t = JammingTable::builtin();
  ASSERT_GE(t.points().size(), 2u);
  // Friction can only loosen a packing: no point above the frictionless one.
  for (const auto& p : t.points()) EXPECT_LE(p.phi_max, t.phi_rcp().value + 2.0 * p.phi_max_err);
}

}  // namespace
}  // namespace dilatant::analysis::jamming_table_test
