// The records summary.json is written from (measure/cell_records.hpp,
// measure/jam_watch.hpp), on rows whose answer is known.
#include "measure/cell_records.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "measure/jam_watch.hpp"

namespace dilatant::measure::cell_records_test {
namespace {

std::vector<FlowRow> rows_of(int n) {
  std::vector<FlowRow> rows(static_cast<std::size_t>(n));
  for (int k = 0; k < n; ++k) {
    rows[k].strain = 0.1 * (k + 1);
    rows[k].duration = 0.5;
    rows[k].steps = 10.0;
  }
  return rows;
}

// The worst residual and the deepest overlap are the rows that hold them,
// with their steps and bodies; sums weigh each row's mean by its steps.
TEST(SolverRecord, NamesTheWorstRowsAndWeighsMeansBySteps) {
  auto rows = rows_of(4);
  rows[1].max_overlap = 0.02;
  rows[1].max_overlap_step = 17;
  rows[1].max_overlap_body_i = 3;
  rows[1].max_overlap_body_j = -2;  // a plane
  rows[2].contact_residual_max = 1e-3;
  rows[2].contact_residual_step = 25;
  rows[2].contact_residual_body_i = 5;
  rows[2].contact_residual_body_j = 8;
  rows[3].contact_residual_max = 1e-4;
  rows[3].contact_residual_step = 33;
  for (int k = 0; k < 4; ++k) rows[static_cast<std::size_t>(k)].mean_iterations = 10.0 * (k + 1);
  rows[0].unconverged_steps = 2.0;
  const SolverRecord s = SolverRecord::of(rows);
  ASSERT_NE(s.deepest, nullptr);
  ASSERT_NE(s.worst_residual, nullptr);
  EXPECT_EQ(s.deepest, &rows[1]);
  EXPECT_EQ(s.worst_residual, &rows[2]);
  nlohmann::json j;
  s.write(j, 0.01);
  EXPECT_EQ(j["max_overlap"].get<double>(), 0.02);
  EXPECT_TRUE(j["overlap_exceeded"].get<bool>());
  EXPECT_EQ(j["max_overlap_step"].get<long long>(), 17);
  EXPECT_EQ(j["max_overlap_bodies"], nlohmann::json({3, -2}));
  EXPECT_EQ(j["contact_residual_max_step"].get<long long>(), 25);
  EXPECT_EQ(j["contact_residual_max"].get<double>(), 1e-3);
  EXPECT_DOUBLE_EQ(j["mean_iterations"].get<double>(), 25.0);  // (10+20+30+40)/4, equal steps
  EXPECT_DOUBLE_EQ(j["frac_steps_unconverged"].get<double>(), 2.0 / 40.0);
}

// A run without rows (stopped in its first interval) has nothing to name.
TEST(SolverRecord, NoRowsNameNothing) {
  nlohmann::json j;
  SolverRecord::of({}).write(j, 0.01);
  EXPECT_EQ(j["max_overlap"].get<double>(), 0.0);
  EXPECT_TRUE(j["max_overlap_step"].is_null());
  EXPECT_TRUE(j["contact_residual_max_step"].is_null());
  EXPECT_FALSE(j["overlap_exceeded"].get<bool>());
}

// mu_eff = <sigma_zx> / <p>, and null where there is no pressure; the tensor
// is written in the paper's stress unit.
TEST(StressRecord, FrictionCoefficientIsTheRatioOfTheMeans) {
  auto rows = rows_of(20);
  for (FlowRow& r : rows) {
    r.stress[tensor_index(kZ, kX)] = 0.3;
    for (int a = 0; a < 3; ++a) r.stress[tensor_index(a, a)] = -1.0;  // p = 1
  }
  nlohmann::json j;
  StressRecord::of(rows, 0.0).write(j, 0.5);
  EXPECT_NEAR(j["mu_eff"].get<double>(), 0.3, 1e-12);
  EXPECT_NEAR(j["pressure"].get<double>(), 2.0, 1e-12);  // 1 / 0.5
  EXPECT_NEAR(j["stress_tensor"][2][0].get<double>(), 0.6, 1e-12);
  EXPECT_NEAR(j["mu_pressure"].get<double>(), 0.3, 1e-12);
  EXPECT_EQ(j["mu_eff_definition"], "shear_stress_measured / pressure");
  nlohmann::json none;
  StressRecord::of(rows_of(20), 0.0).write(none, 1.0);
  EXPECT_TRUE(none["mu_eff"].is_null());
  EXPECT_TRUE(none["mu_pressure"].is_null());
}

// Under an imposed normal stress P (the pressure-imposed cell) mu_eff is
// Boyer, Guazzelli & Pouliquen's tau / P, the imposed P exact, so its error is
// sigma_zx's over P; mu_pressure keeps sigma_zx / p.
TEST(StressRecord, UnderAnImposedNormalStressMuEffIsShearOverTheImposedOne) {
  auto rows = rows_of(20);
  for (std::size_t k = 0; k < rows.size(); ++k) {
    rows[k].stress[tensor_index(kZ, kX)] = k % 2 ? 0.25 : 0.35;             // mean 0.3
    for (int a = 0; a < 3; ++a) rows[k].stress[tensor_index(a, a)] = -1.0;  // p = 1
  }
  nlohmann::json j;
  const StressRecord record = StressRecord::of(rows, 0.0);
  record.write(j, 1.0, 0.6);
  EXPECT_NEAR(j["mu_eff"].get<double>(), 0.5, 1e-12);
  EXPECT_NEAR(j["mu_eff_err"].get<double>(), record.shear.error / 0.6, 1e-15);
  EXPECT_GT(j["mu_eff_err"].get<double>(), 0.0);
  EXPECT_NEAR(j["mu_pressure"].get<double>(), 0.3, 1e-12);
  EXPECT_EQ(j["mu_eff_definition"], "shear_stress_measured / normal_stress_imposed");
}

// Dissipations are reported positive; the wall forces are null without walls.
TEST(EnergyAndWallRecords, SignsAndWallOnlyFields) {
  auto rows = rows_of(20);
  for (FlowRow& r : rows) {
    r.power_drive = 2.0;
    r.power_normal = -1.5;
    r.power_bl = -0.5;
    r.bottom_force_x = -4.0;
  }
  nlohmann::json j;
  EnergyRecord::of(rows, 0.0).write(j);
  EXPECT_NEAR(j["power_injected"].get<double>(), 2.0, 1e-12);
  EXPECT_NEAR(j["power_impacts"].get<double>(), 1.5, 1e-12);
  EXPECT_NEAR(j["power_friction_bl"].get<double>(), 0.5, 1e-12);
  WallForceRecord::of(rows, 0.0, true).write(j);
  EXPECT_NEAR(j["bottom_wall_force_x"].get<double>(), -4.0, 1e-12);
  WallForceRecord::of(rows, 0.0, false).write(j);
  EXPECT_TRUE(j["bottom_wall_force_x"].is_null());
}

// A jam is decided at each window's end: less than kJamStrain in kJamWindow.
TEST(JamWatch, DecidesAtTheWindowsEnd) {
  JamWatch w;
  w.observe(JamWatch::kJamWindow * 0.5, 0.0);  // inside the first window: undecided
  EXPECT_FALSE(w.jammed);
  w.observe(JamWatch::kJamWindow, 0.5 * JamWatch::kJamStrain);
  EXPECT_TRUE(w.jammed);
  EXPECT_EQ(w.window_time, JamWatch::kJamWindow);
  w.observe(2.0 * JamWatch::kJamWindow, 3.0 * JamWatch::kJamStrain);  // it moved again
  EXPECT_FALSE(w.jammed);
}

}  // namespace
}  // namespace dilatant::measure::cell_records_test
