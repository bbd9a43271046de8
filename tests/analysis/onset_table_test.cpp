// The frictional onset (analysis/onset_table.hpp): the prefactor measured on
// one onset reproduces that onset exactly, the prediction scales as 1/s_c
// (the paper's gamma_dot_c ~ eta_f I^2/(s_c rho R^2)), the nearest measured
// friction is used with all its seeds, and malformed rows are refused by line.
#include "analysis/onset_table.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>

#include "io/input_error.hpp"

namespace dilatant::analysis::onset_table_test {
namespace {

constexpr const char* kOnsets =
    "mu0,phi_bulk,s_c,onset_rate,inertial_number,model,source\n"
    "0.1,0.61,5e-05,0.03,0.0116,literal,a\n"
    "\n"
    "0.4,0.61,5e-05,0.125,0.0177,literal,b\n";

TEST(OnsetTable, PrefactorReproducesTheMeasuredOnsetAndScalesAsOneOverSc) {
  const auto t = OnsetTable::parse(NumericCsv::from_text(kOnsets, "o.csv"));
  ASSERT_EQ(t.onsets().size(), 2u);
  const auto at = predict_onset(t, 0.4, 0.6, 5e-5);
  ASSERT_TRUE(at.available);
  ASSERT_EQ(at.measured.size(), 1u);
  EXPECT_EQ(at.measured[0].source, "b");
  // One curve: its own rate is the range (the log average rounds in the last bits).
  EXPECT_NEAR(at.rate_low, at.rate, 1e-14);
  EXPECT_NEAR(at.rate_high, at.rate, 1e-14);
  EXPECT_NEAR(at.scale, 0.0177 * 0.0177 / 5e-5, 1e-13);
  EXPECT_NEAR(at.prefactor, 0.125 / (0.0177 * 0.0177 / 5e-5), 1e-15);
  EXPECT_NEAR(at.rate, 0.125, 1e-12);  // C I^2/s_c at the measured s_c
  // Ten times s_c: the contacts leave the HD branch at a rate ten times lower.
  EXPECT_NEAR(predict_onset(t, 0.4, 0.6, 5e-4).rate, 0.0125, 1e-12);
}

TEST(OnsetTable, UsesTheNearestMeasuredFriction) {
  const auto t = OnsetTable::parse(NumericCsv::from_text(kOnsets, "o.csv"));
  EXPECT_EQ(predict_onset(t, 0.0, 0.6, 5e-5).measured.at(0).source, "a");
  EXPECT_EQ(predict_onset(t, 0.2, 0.6, 5e-5).measured.at(0).source, "a");
  EXPECT_EQ(predict_onset(t, 1.0, 0.6, 5e-5).measured.at(0).source, "b");
  const auto empty = OnsetTable::parse(
      NumericCsv::from_text("mu0,phi_bulk,s_c,onset_rate,inertial_number,model,source\n", "e.csv"));
  EXPECT_FALSE(predict_onset(empty, 0.4, 0.6, 5e-5).available);
}

// Two seeds of one state give one prediction: C and I_c are averaged in log,
// so the rate is the geometric mean of the two curves' own rates, which
// bound it; a row at another phi_bulk, or of another model, is another state
// and stays out.
TEST(OnsetTable, AveragesTheSeedsOfOneStateInLog) {
  const auto t = OnsetTable::parse(
      NumericCsv::from_text("mu0,phi_bulk,s_c,onset_rate,inertial_number,seed,model,source\n"
                            "0.4,0.6097,5e-05,1.8,0.040,1,literal,s1\n"
                            "0.4,0.6099,5e-05,1.2,0.030,2,literal,s2\n"
                            "0.4,0.58,5e-05,9.0,0.050,1,literal,loose\n"
                            "0.4,0.6098,5e-05,30.0,0.050,1,films,another model\n",
                            "o.csv"));
  const auto at = predict_onset(t, 0.4, 0.61, 5e-5);
  ASSERT_EQ(at.measured.size(), 2u);
  EXPECT_EQ(at.measured[0].seed, 1);
  EXPECT_EQ(at.measured[1].seed, 2);
  EXPECT_NEAR(at.rate, std::sqrt(1.8 * 1.2), 1e-12);
  EXPECT_NEAR(at.inertial_number, std::sqrt(0.040 * 0.030), 1e-15);
  EXPECT_NEAR(at.rate_low, 1.2, 1e-12);
  EXPECT_NEAR(at.rate_high, 1.8, 1e-12);
  EXPECT_NEAR(at.phi_bulk, 0.6098, 1e-12);
  // At s_c ten times smaller every curve's rate, and so the mean, is ten times higher.
  const auto tenth = predict_onset(t, 0.4, 0.61, 5e-6);
  EXPECT_NEAR(tenth.rate, 10.0 * at.rate, 1e-12 * tenth.rate);
  EXPECT_NEAR(tenth.rate_high, 18.0, 1e-11);
  EXPECT_EQ(predict_onset(t, 0.4, 0.58, 5e-5).measured.at(0).source, "loose");
}

TEST(OnsetTable, RefusesRowsByLine) {
  using ::testing::HasSubstr;
  const std::string head = "mu0,phi_bulk,s_c,onset_rate,inertial_number,model,source\n";
  for (const auto& [row, what] : std::vector<std::pair<std::string, std::string>>{
           {"0.1,0.61,0,0.03,0.01,l,a", "o.csv:2"},
           {"0.1,0.61,5e-5,x,0.01,l,a", "onset_rate = \"x\""},
           {"-1,0.61,5e-5,0.03,0.01,l,a", "o.csv:2"}}) {
    try {
      OnsetTable::parse(NumericCsv::from_text(head + row, "o.csv"));
      ADD_FAILURE() << row;
    } catch (const InputError& e) {
      EXPECT_THAT(e.what(), HasSubstr(what));
    }
  }
  EXPECT_THROW(OnsetTable::parse(NumericCsv::from_text("mu0,s_c\n", "o.csv")), InputError);
  // A seed column holds whole numbers.
  const std::string seeded = "mu0,phi_bulk,s_c,onset_rate,inertial_number,seed,model,source\n";
  for (const char* seed : {"1.5", "-1"}) {
    try {
      OnsetTable::parse(
          NumericCsv::from_text(seeded + "0.1,0.61,5e-5,0.03,0.01," + seed + ",l,a", "o.csv"));
      ADD_FAILURE() << seed;
    } catch (const InputError& e) {
      EXPECT_THAT(e.what(), HasSubstr("o.csv:2"));
      EXPECT_THAT(e.what(), HasSubstr("need a whole number >= 0"));
    }
  }
}

TEST(OnsetTable, BuiltInTableIsMeasuredAndBelowThePrefactorOneScale) {
  // The shipped onsets (docs/jamming.md "The onset scale"): every one comes
  // before the paper's scale with prefactor 1 (C < 1: contacts slide slower
  // and carry more than the mean field says), and every mu0 has two seeds.
  const auto t = OnsetTable::builtin();
  ASSERT_FALSE(t.onsets().empty());
  for (const auto& o : t.onsets()) {
    EXPECT_LT(o.onset_rate, onset_rate_scale(o.inertial_number, o.s_c)) << o.source;
    EXPECT_FALSE(o.source.empty());
    EXPECT_EQ(predict_onset(t, o.mu0, o.phi_bulk, o.s_c).measured.size(), 2u) << o.mu0;
  }
}

}  // namespace
}  // namespace dilatant::analysis::onset_table_test
