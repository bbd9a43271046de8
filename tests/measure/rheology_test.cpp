// The cell's rheology from its time series (measure/rheology.hpp): the
// definitions of gamma_dot, eta, I and J on series whose answer is known.
#include "measure/rheology.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

namespace dilatant::rheology_test {
namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();

// Rows of equal duration, one per 0.05 strain, with the wall velocity and
// normal stress given by functions of the row index.
template <class V, class P>
std::vector<FlowRow> series(int n, V velocity, P pressure) {
  std::vector<FlowRow> rows;
  for (int k = 0; k < n; ++k) {
    FlowRow r;
    r.strain = 0.05 * (k + 1);
    r.duration = 0.25;  // exact in binary: the blocks split exactly
    r.wall_velocity = velocity(k);
    r.normal_stress = pressure(k);
    rows.push_back(r);
  }
  return rows;
}

// lambda = 10 with tau = rho_p = R = 1: eta_f = 0.1, rate unit 0.1, stress unit 0.01.
TEST(CellUnits, FollowFromLambda) {
  const CellUnits u = make_cell_units(1.0, 1.0, 1.0, 10.0);
  EXPECT_DOUBLE_EQ(u.eta_f, 0.1);
  EXPECT_DOUBLE_EQ(u.rate_unit, 0.1);
  EXPECT_DOUBLE_EQ(u.stress_unit, 0.01);
  // tau = 4, rho_p = 2, R = 0.5: eta_f = sqrt(8) 0.5 / lambda; the units keep the symbols.
  const CellUnits v = make_cell_units(4.0, 2.0, 0.5, 2.0);
  EXPECT_NEAR(v.eta_f, std::sqrt(8.0) * 0.5 / 2.0, 4 * kEps);
  EXPECT_NEAR(v.rate_unit, v.eta_f / (2.0 * 0.25), 4 * kEps);
  EXPECT_NEAR(v.stress_unit, v.eta_f * v.eta_f / (2.0 * 0.25), 4 * kEps);
}

// A steady wall speed V over Lz: gamma_dot = V/Lz, eta = tau/(gamma_dot eta_f),
// I = gamma_dot R sqrt(rho_p/P), J = eta_f gamma_dot / P; rows inside the
// transient are not averaged.
TEST(Rheology, SteadyFlowGivesTheDefinitions) {
  const double lz = 12.0, v = 3.0, p = 50.0;
  auto rows = series(
      60, [&](int k) { return k < 20 ? 100.0 : v; }, [&](int k) { return k < 20 ? -1.0 : p; });
  const CellUnits u = make_cell_units(1.0, 1.0, 1.0, 30.0);
  const Rheology r = steady_rheology(
      rows, 1.0, {.height = lz, .shear_stress = 1.0, .radius = 1.0, .density = 1.0}, u);
  EXPECT_EQ(r.wall_velocity.samples, 40);
  EXPECT_NEAR(r.shear_rate, v / lz, 4 * kEps * v / lz);
  EXPECT_NEAR(r.viscosity, 1.0 / (v / lz) / u.eta_f, 1e-12 * r.viscosity);
  EXPECT_NEAR(r.normal_stress.mean, p, 4 * kEps * p);
  EXPECT_NEAR(r.inertial_number, v / lz * std::sqrt(1.0 / p), 1e-14);
  EXPECT_NEAR(r.viscous_number, u.eta_f * v / lz / p, 1e-16);
  // A constant series has no scatter: the error bars are zero but for the
  // round-off of the one-pass variance <x^2> - <x>^2, ~sqrt(eps) |x|.
  EXPECT_LE(r.shear_rate_err, 4.0 * std::sqrt(kEps) * v / lz);
  EXPECT_LE(r.viscosity_err, 4.0 * std::sqrt(kEps) * r.viscosity);
}

// tau is imposed exactly, so eta = tau/gamma_dot carries the relative error of
// V, whatever that error is: here block means alternating 1.8 / 2.2.
TEST(Rheology, ViscosityCarriesTheRelativeErrorOfTheShearRate) {
  // 10 blocks of 4 rows each; block b has V = 2 + 0.2 (-1)^b.
  auto rows = series(
      40, [](int k) { return 2.0 + ((k / 4) % 2 == 0 ? 0.2 : -0.2); }, [](int) { return 1.0; });
  const Rheology r = steady_rheology(
      rows, 0.0, {.height = 1.0, .shear_stress = 1.0, .radius = 1.0, .density = 1.0},
      make_cell_units(1.0, 1.0, 1.0, 1.0));
  // Block means +-0.2 about 2: sample variance 0.04 * 10/9, error sqrt(var/10).
  const double error = std::sqrt(0.04 * 10.0 / 9.0 / 10.0);
  EXPECT_NEAR(r.wall_velocity.error, error, 1e-12);
  EXPECT_NEAR(r.relative_error, error / 2.0, 1e-12);
  EXPECT_NEAR(r.viscosity_err / r.viscosity, error / 2.0, 1e-12);
  EXPECT_NEAR(r.shear_rate_err / r.shear_rate, error / 2.0, 1e-12);
}

// Under rate control (the Lees–Edwards box) V is imposed and tau measured:
// eta = <sigma_zx> / gamma_dot, its error that of <sigma_zx> alone, and the
// stress reported is the measured one, not an applied one. Block means of
// sigma_zx alternate 0.9 / 1.1 about 1, V is constant.
TEST(Rheology, UnderRateControlEtaIsTheMeasuredStressOverTheImposedRate) {
  const double lz = 8.0, v = 2.0;
  auto rows = series(
      40, [&](int) { return v; }, [](int) { return 1.0; });
  for (std::size_t k = 0; k < rows.size(); ++k) {
    const double tau = 1.0 + ((k / 4) % 2 == 0 ? 0.1 : -0.1);
    rows[k].stress[tensor_index(kZ, kX)] = tau;  // sigma is symmetric
    rows[k].stress[tensor_index(kX, kZ)] = tau;
  }
  const CellUnits u = make_cell_units(1.0, 1.0, 1.0, 10.0);
  const Rheology r = steady_rheology(rows, 0.0,
                                     {.height = lz,
                                      .shear_stress = 123.0,  // ignored: not applied
                                      .rate_controlled = true,
                                      .radius = 1.0,
                                      .density = 1.0},
                                     u);
  const double error = std::sqrt(0.01 * 10.0 / 9.0 / 10.0);  // as the test above, +-0.1
  EXPECT_NEAR(r.shear_rate, v / lz, 4 * kEps * v / lz);
  EXPECT_NEAR(r.shear_stress, 1.0, 1e-12);
  EXPECT_NEAR(r.shear_stress_err, error, 1e-12);
  EXPECT_NEAR(r.viscosity, 1.0 / (v / lz) / u.eta_f, 1e-12 * r.viscosity);
  EXPECT_NEAR(r.viscosity_err, error / (v / lz) / u.eta_f, 1e-12 * r.viscosity);
  // V is exact: its error bar is round-off only, and so is gamma_dot's.
  EXPECT_LE(r.shear_rate_err, 4.0 * std::sqrt(kEps) * v / lz);
}

// Under stress control the stress reported is the applied one, exact, even
// when the particles' measured stress differs from it (a transient, or the
// wall layers' share): eta is tau / gamma_dot with the error of V alone.
TEST(Rheology, UnderStressControlEtaIsTheAppliedStressOverTheMeasuredRate) {
  auto rows = series(
      40, [](int k) { return 2.0 + ((k / 4) % 2 == 0 ? 0.2 : -0.2); }, [](int) { return 1.0; });
  for (FlowRow& row : rows) row.stress[tensor_index(kZ, kX)] = 7.0;
  const Rheology r = steady_rheology(
      rows, 0.0, {.height = 1.0, .shear_stress = 3.0, .radius = 1.0, .density = 1.0},
      make_cell_units(1.0, 1.0, 1.0, 1.0));
  EXPECT_EQ(r.shear_stress, 3.0);
  EXPECT_EQ(r.shear_stress_err, 0.0);
  EXPECT_NEAR(r.viscosity, 3.0 / 2.0, 1e-12);
  EXPECT_NEAR(r.viscosity_err / r.viscosity, r.relative_error, 1e-14);
}

// The summary's keys in the paper's units, and a jam: no eta, gamma_dot 0.
TEST(Rheology, WritesThePapersUnitsAndNoViscosityForAJam) {
  auto rows = series(
      20, [](int) { return 3.0; }, [](int) { return 50.0; });
  const CellUnits u = make_cell_units(1.0, 1.0, 1.0, 10.0);
  const Rheology r = steady_rheology(
      rows, 0.0, {.height = 12.0, .shear_stress = 1.0, .radius = 1.0, .density = 1.0}, u);
  nlohmann::json flowing, jammed;
  write_rheology(flowing, r, u, false);
  write_rheology(jammed, r, u, true);
  EXPECT_NEAR(flowing["shear_stress"].get<double>(), 1.0 / u.stress_unit, 1e-12 / u.stress_unit);
  EXPECT_NEAR(flowing["gamma_dot"].get<double>(), 3.0 / 12.0 / u.rate_unit, 1e-12 / u.rate_unit);
  EXPECT_NEAR(flowing["normal_stress"].get<double>(), 50.0 / u.stress_unit, 1e-12 / u.stress_unit);
  EXPECT_DOUBLE_EQ(flowing["eta"].get<double>(), r.viscosity);
  EXPECT_EQ(jammed["gamma_dot"].get<double>(), 0.0);
  EXPECT_TRUE(jammed["eta"].is_null());
  EXPECT_TRUE(jammed["eta_err"].is_null());
}

// A cell that does not move (jammed) has no viscosity to report: 0, not inf.
TEST(Rheology, ACellAtRestHasNoViscosity) {
  auto rows = series(
      30, [](int) { return 0.0; }, [](int) { return 0.0; });
  const Rheology r = steady_rheology(
      rows, 0.0, {.height = 10.0, .shear_stress = 1.0, .radius = 1.0, .density = 1.0},
      make_cell_units(1.0, 1.0, 1.0, 10.0));
  EXPECT_EQ(r.shear_rate, 0.0);
  EXPECT_EQ(r.viscosity, 0.0);
  EXPECT_EQ(r.relative_error, 0.0);
  EXPECT_EQ(r.inertial_number, 0.0);
  EXPECT_EQ(r.viscous_number, 0.0);
  EXPECT_EQ(relative_viscosity(1.0, 0.0, 0.1), 0.0);
}

}  // namespace
}  // namespace dilatant::rheology_test
