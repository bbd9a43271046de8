// The pressure-imposed Lees–Edwards cell (cell.control = "pressure";
// boundary/image_drive.hpp, docs/shear-cell.md "The pressure-imposed cell"):
// dry frictional grains (Coulomb friction, no fluid) sheared at a fixed rate
// under two normal stresses. Tolerances are the runs' own block errors at 3
// sigma (measure/flow_series.hpp), the errors themselves bounded so that a
// noisy run cannot pass more easily.
//
// The physics (GDR MiDi, Eur. Phys. J. E 14, 341 (2004); da Cruz et al., PRE
// 72, 021309 (2005)): at fixed gamma_dot a higher pressure P is a lower
// inertial number I = gamma_dot R sqrt(rho_p / P), and phi(I) decreases with
// I, so the denser packing is the one under the higher pressure.
//
// PressureCell (its own ctest entry with PressureCellFilms): both dry runs in
// one process.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "drivers/cell_run_helpers.hpp"

namespace dilatant::pressure_cell_test {
namespace {

constexpr double kRate = 0.1;
constexpr double kLowP = 0.5, kHighP = 8.0;

std::vector<std::string> dry_cell(double p) {
  return {"cell.boundary=\"lees-edwards\"",
          "cell.control=\"pressure\"",
          "cell.size=[8.0, 5.0, 9.0]",
          "cell.shear_rate=" + std::to_string(kRate),
          "cell.normal_stress=" + std::to_string(p),
          "friction.law=\"coulomb\"",
          "friction.mu0=0.4",
          "fluid.lambda=1.0",
          "fluid.lubrication=none",
          "fluid.drag=none",
          "run.strain=5.0",
          "run.transient_strain=2.0",
          "run.output_interval=0.02",
          "run.snapshot_interval=0.0"};
}

// examples/pressure-cell.toml's suspension (Stribeck friction, squeeze films,
// Stokes drag, eta_f = 10, built at phi 0.51, gamma_dot 0.002, P = 1), with the
// lid's mass M and the run's strain and transient.
std::vector<std::string> films_cell(const std::string& mass, const std::string& strain,
                                    const std::string& transient) {
  return {"cell.boundary=\"lees-edwards\"",
          "cell.control=\"pressure\"",
          "cell.size=[8.0, 5.0, 9.0]",
          "cell.phi=0.51",
          "cell.shear_rate=0.002",
          "cell.normal_stress=1.0",
          "cell.boundary_mass=" + mass,
          "friction.law=\"stribeck\"",
          "friction.mu0=0.4",
          "fluid.lambda=0.1",
          "fluid.lubrication=\"normal\"",
          "fluid.drag=\"stokes\"",
          "run.strain=" + strain,
          "run.transient_strain=" + transient,
          "run.output_interval=0.02",
          "run.snapshot_interval=0.0"};
}

class PressureCell : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    low_ = test::run_cell_summary("pressure_low", dry_cell(kLowP));
    high_ = test::run_cell_summary("pressure_high", dry_cell(kHighP));
  }
  static nlohmann::json low_, high_;
};
nlohmann::json PressureCell::low_;
nlohmann::json PressureCell::high_;

// The lid's feedback M dW/dt = A (p - P) holds the height where the flow
// transmits the imposed normal stress: the measured -sigma_zz is P within its
// error, at either pressure; the rate is the imposed one, exactly.
TEST_F(PressureCell, TheMeasuredNormalStressIsTheImposedOne) {
  for (const auto* s : {&low_, &high_}) {
    const nlohmann::json& j = *s;
    EXPECT_EQ(j["control"], "pressure");
    EXPECT_FALSE(j["jammed"].get<bool>());
    const double p = j["normal_stress_imposed"], measured = j["normal_stress"];
    const double err = j["normal_stress_err"];
    ASSERT_GT(err, 0.0);
    ASSERT_LT(err, 0.2 * p);
    EXPECT_NEAR(measured, p, 3.0 * err) << "P = " << p;
    const double rate = j["gamma_dot"], rate_err = j["gamma_dot_err"];
    EXPECT_NEAR(rate * j["eta_f"].get<double>(), kRate, 1e-9 * kRate);
    EXPECT_LT(rate_err, 1e-9 * rate);
    // J and I of the imposed rate and the measured pressure.
    EXPECT_NEAR(j["inertial_number"].get<double>(), kRate / std::sqrt(measured), 1e-9);
  }
}

// mu_eff is Boyer, Guazzelli & Pouliquen's tau / P with P the imposed normal
// stress (measure/cell_records.hpp); the flow's own -sigma_zz equals P on
// average, so tau over the measured normal stress agrees with it within the
// normal stress's block error at 3 sigma (tau's errors cancel in the ratio of
// the two: mu_eff (p - P) / p). mu_pressure is tau over -tr(sigma)/3.
TEST_F(PressureCell, MuEffIsTheShearStressOverTheImposedNormalStress) {
  for (const auto* s : {&low_, &high_}) {
    const nlohmann::json& j = *s;
    EXPECT_EQ(j["mu_eff_definition"], "shear_stress_measured / normal_stress_imposed");
    const double tau = j["shear_stress_measured"], p = j["normal_stress_imposed"];
    const double mu = j["mu_eff"];
    EXPECT_NEAR(mu, tau / p, 1e-12 * mu);
    EXPECT_NEAR(j["mu_eff_err"].get<double>(), j["shear_stress_measured_err"].get<double>() / p,
                1e-12 * mu);
    const double measured = j["normal_stress"], err = j["normal_stress_err"];
    EXPECT_NEAR(tau / measured, mu, 3.0 * mu * err / measured) << "P = " << p;
    EXPECT_NEAR(j["mu_pressure"].get<double>(), tau / j["pressure"].get<double>(), 1e-12 * mu);
  }
}

// Steady: the volume fraction and the friction coefficient are averages with
// small errors, mu_eff that of a frictional flow (between mu0 / 4 and 1), the
// height consistent with phi (H = N v / (A phi)), the profile linear.
TEST_F(PressureCell, PhiAndMuEffAreSteady) {
  for (const auto* s : {&low_, &high_}) {
    const nlohmann::json& j = *s;
    const double phi = j["phi_bulk"], phi_err = j["phi_bulk_err"];
    ASSERT_GT(phi_err, 0.0);
    EXPECT_LT(phi_err, 0.01);
    EXPECT_GT(phi, 0.4);
    EXPECT_LT(phi, 0.66);
    const double mu = j["mu_eff"], mu_err = j["mu_eff_err"];
    EXPECT_GT(mu, 0.1);
    EXPECT_LT(mu, 1.0);
    EXPECT_LT(mu_err, 0.2 * mu);
    const double h0_phi = 9.0 * j["phi_box"].get<double>();
    EXPECT_NEAR(j["box_height_mean"].get<double>() * phi, h0_phi, 0.02 * h0_phi);
    EXPECT_TRUE(j["profile_consistent"].get<bool>());
    EXPECT_TRUE(j["steady"].get<bool>())
        << j["phi_bulk_drift"] << " +- " << j["phi_bulk_drift_err"];
    EXPECT_TRUE(j["valid"].get<bool>()) << j["invalid_reasons"];
  }
}

// phi(I) decreases: the higher pressure (16 times, I 4 times lower) packs
// denser, by more than 3 combined error bars.
TEST_F(PressureCell, AHigherPressureAtTheSameRatePacksDenser) {
  const double lo = low_["phi_bulk"], hi = high_["phi_bulk"];
  const double err =
      std::hypot(low_["phi_bulk_err"].get<double>(), high_["phi_bulk_err"].get<double>());
  EXPECT_GT(hi - lo, 3.0 * err) << "phi(P = " << kLowP << ") = " << lo << ", phi(P = " << kHighP
                                << ") = " << hi << " +- " << err;
  EXPECT_GT(low_["inertial_number"].get<double>(), high_["inertial_number"].get<double>());
}

// mu(I) increases (GDR MiDi 2004; Jop, Forterre & Pouliquen, Nature 441, 727
// (2006)): the lower pressure, at 4 times the inertial number, has the larger
// effective friction, by more than 3 combined error bars.
TEST_F(PressureCell, MuEffRisesWithTheInertialNumber) {
  const double lo = low_["mu_eff"], hi = high_["mu_eff"];
  const double err =
      std::hypot(low_["mu_eff_err"].get<double>(), high_["mu_eff_err"].get<double>());
  EXPECT_GT(lo - hi, 3.0 * err) << "mu_eff(P = " << kLowP << ") = " << lo
                                << ", mu_eff(P = " << kHighP << ") = " << hi << " +- " << err;
}

// Films and drag (examples/pressure-cell.toml: Stribeck friction, squeeze
// films, Stokes drag, eta_f = 10): the viscous regime, J = eta_f gamma_dot / P
// = 0.02 at a Stokes number I^2 / J = 2e-4. The lid (heavy enough not to
// bounce: docs/shear-cell.md "Films and drag") holds the measured -sigma_zz
// at P, and the point is steady and valid. One run, about 7 s.
TEST(PressureCellFilms, HoldsThePressureInTheViscousRegime) {
  const nlohmann::json j =
      test::run_cell_summary("pressure_films", films_cell("1e4", "4.0", "1.5"));
  EXPECT_FALSE(j["jammed"].get<bool>());
  const double p = j["normal_stress_imposed"], measured = j["normal_stress"];
  const double err = j["normal_stress_err"];
  ASSERT_GT(err, 0.0);
  ASSERT_LT(err, 0.05 * p);
  EXPECT_NEAR(measured, p, 3.0 * err);
  // J of the imposed rate and the measured pressure: 10 x 0.002 / 1.
  EXPECT_NEAR(j["viscous_number"].get<double>(), 0.02, 3.0 * 0.02 * err / p);
  EXPECT_LT(j["box_height_fluctuation"].get<double>(), 0.05);
  EXPECT_TRUE(j["steady"].get<bool>()) << j["phi_bulk_drift"] << " +- " << j["phi_bulk_drift_err"];
  EXPECT_TRUE(j["valid"].get<bool>()) << j["invalid_reasons"];
  const double phi = j["phi_bulk"], mu = j["mu_eff"];
  EXPECT_GT(phi, 0.5);
  EXPECT_LT(phi, 0.64);
  EXPECT_GT(mu, 0.1);
  EXPECT_LT(mu, 1.5);
}

// The lid with films and drag at its default mass (the top-wall mass, 26 in
// this box): the regression of docs/shear-cell.md "Films and drag". Before the
// lid's speed entered the contacts (Contact::dilation_drift) and its update
// took the films' resistance implicitly (boundary/lid_resistance.hpp), this
// run's lid bounced: its height swung by 45% of a mean of 13.3 R (built 9),
// phi_bulk 0.39, 42,450 steps for strain 0.5. The films damp the lid now: a
// stiff film's resistance c makes the explicit step's factor 1 - dt A c / M
// far below -1, the linearly implicit one 1 - dt A c / (M + dt A c) lies in
// (0, 1]. Tolerances: the height's fluctuation below the 5% that makes a point
// invalid; the measured -sigma_zz at P within 3 of its block errors (the lid's
// equation averaged over the window makes <p> - P the lid's momentum change
// over A T, which a lid that stays put keeps below the stress's own noise).
// About 4 s.
TEST(PressureCellFilms, TheDefaultLidStaysPutUnderFilmsAndDrag) {
  const nlohmann::json j =
      test::run_cell_summary("pressure_films_default_lid", films_cell("0", "0.5", "0.1"));
  ASSERT_FALSE(j["jammed"].get<bool>());
  const double fluctuation = j["box_height_fluctuation"], height = j["box_height_mean"];
  ASSERT_TRUE(std::isfinite(height));
  EXPECT_LT(fluctuation, 0.05);
  // The height the packing needs at phi_bulk, not a blown-up box: H phi = H0 phi_box.
  const double h0_phi = 9.0 * j["phi_box"].get<double>();
  EXPECT_NEAR(height * j["phi_bulk"].get<double>(), h0_phi, 0.02 * h0_phi);
  EXPECT_LT(height, 9.0);  // compacted from phi 0.51, as the heavy lid's run does
  const double p = j["normal_stress_imposed"], measured = j["normal_stress"];
  const double err = j["normal_stress_err"];
  ASSERT_GT(err, 0.0);
  ASSERT_LT(err, 0.01 * p);
  EXPECT_NEAR(measured, p, 3.0 * err);
  EXPECT_TRUE(j["valid"].get<bool>()) << j["invalid_reasons"];
}

}  // namespace
}  // namespace dilatant::pressure_cell_test
