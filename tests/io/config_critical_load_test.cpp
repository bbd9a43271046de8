// friction.law = "critical_load" and friction.critical_load: the conversion
// from the paper's force unit eta_f^2/rho_p to code units (docs/model.md
// "Friction"), the onset stress the resolved config reports, and bad input
// naming the key.
#include <fmt/format.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "io/config.hpp"
#include "io/input_error.hpp"
#include "io/io_test_files.hpp"

namespace dilatant::config_critical_load_test {
namespace {

using ::testing::HasSubstr;

Config parse(const std::string& text, const std::vector<std::string>& overrides = {}) {
  return parse_config(text, "test.toml", "/base", overrides);
}

const std::string kLaw = "[friction]\nlaw = 'critical_load'\ncritical_load = 10.0\n";
const std::string kScene = "[scene]\nparticles = 'p.csv'\n[run]\ntime = 1.0\n";

TEST(ConfigCriticalLoad, IsNoneUnderTheOtherLaws) {
  const Config c = parse("[cell]\n");
  EXPECT_EQ(c.friction.critical_load, 0.0);
  EXPECT_EQ(c.critical_load(), 0.0);
  EXPECT_EQ(c.resolved.at_path("friction.critical_load").value<double>(), 0.0);
  EXPECT_EQ(friction_law_name(FrictionLawKind::Stribeck), "stribeck");
  EXPECT_EQ(friction_law_name(FrictionLawKind::CriticalLoad), "critical_load");
}

// eta_f = sqrt(tau rho_p) R / lambda and F*_code = F* eta_f^2 / rho_p: with
// tau 8, rho_p 2, R 0.5, lambda 2 (numbers exact in binary), eta_f = 1 and
// eta_f^2 / rho_p = 0.5, so F*_code = 5 = F* tau R^2 / lambda^2.
TEST(ConfigCriticalLoad, TheCellConvertsThePapersForceUnitOnce) {
  const Config c = parse(
      "[cell]\nshear_stress = 8.0\nradius_min = 0.4\nradius_max = 0.5\n[particles]\n"
      "density = 2.0\n[fluid]\nlambda = 2.0\n" +
      kLaw);
  EXPECT_EQ(c.friction.law, FrictionLawKind::CriticalLoad);
  EXPECT_EQ(c.friction.critical_load, 10.0);  // as given
  EXPECT_EQ(c.critical_load(), 5.0);
  // The resolved config says it, with the onset stress sigma* = F*/R^2 = 20 in
  // code units: 10 in the paper's units (their stress unit eta_f^2/(rho_p R^2)
  // is 2 here), 2.5 x tau, which the applied stress, lambda^2 in the paper's
  // units, meets at lambda = 2 sqrt(2.5) = sqrt(10).
  const std::string text = resolved_toml(c);
  EXPECT_THAT(text, HasSubstr("# critical_load in code units = 5.0  (derived:"));
  EXPECT_THAT(text, HasSubstr("sigma* = critical_load / radius_max^2 = 10.0 (paper's units) = "
                              "2.5 x shear_stress"));
  EXPECT_THAT(text, HasSubstr(fmt::format("at lambda = {}", 2.0 * std::sqrt(2.5))));
  EXPECT_NEAR(2.0 * std::sqrt(2.5), std::sqrt(10.0), 4 * std::numeric_limits<double>::epsilon());
  // ... as comments: it loads back to the same configuration.
  EXPECT_EQ(parse(text).resolved, c.resolved);
}

// The key is a material constant: a lambda sweep moves the applied stress
// (lambda^2 in the paper's units) while F* stays, so in code units F* falls as
// 1 / lambda^2 and the sweep crosses it. A critical load fixed in code units
// would scale with the applied stress and never be crossed.
TEST(ConfigCriticalLoad, ALambdaSweepMovesTheCodeUnitLoadAsOneOverLambdaSquared) {
  for (const double lambda : {0.1, 1.0, 10.0, 1000.0}) {
    const Config c = parse("[cell]\n" + kLaw, {fmt::format("fluid.lambda={}", lambda)});
    // Five roundings (sqrt, /lambda, square, x F*, x lambda^2 here): 8 eps.
    EXPECT_NEAR(c.critical_load() * lambda * lambda, 10.0,
                8 * std::numeric_limits<double>::epsilon() * 10.0)
        << lambda;
  }
}

TEST(ConfigCriticalLoad, ASceneTakesItInItsOwnUnits) {
  const Config s = parse(kScene + "[fluid]\neta_f = 1e-3\n" + kLaw);
  EXPECT_EQ(s.critical_load(), 10.0);
  EXPECT_EQ(parse(resolved_toml(s)).critical_load(), 10.0);
}

struct BadInput {
  std::string name;
  std::string toml;
  std::vector<std::string> overrides;
  std::string expected;
};

void PrintTo(const BadInput& bad, std::ostream* os) { *os << bad.name; }

class ConfigCriticalLoadBadInput : public ::testing::TestWithParam<BadInput> {};

TEST_P(ConfigCriticalLoadBadInput, ThrowsOneLineNamingTheKey) {
  const auto& bad = GetParam();
  const auto message = test::input_error_message([&] { parse(bad.toml, bad.overrides); });
  EXPECT_THAT(message, HasSubstr(bad.expected));
  EXPECT_THAT(message, ::testing::Not(HasSubstr("\n")));
}

INSTANTIATE_TEST_SUITE_P(
    Config, ConfigCriticalLoadBadInput,
    ::testing::Values(
        BadInput{"LawWithoutTheLoad",
                 "[cell]\n[friction]\nlaw = 'critical_load'\n",
                 {},
                 "test.toml:3: friction.law = \"critical_load\": needs friction.critical_load > 0"},
        BadInput{"LoadZero",
                 "[cell]\n" + kLaw,
                 {"friction.critical_load=0"},
                 "--set friction.critical_load = 0: must be > 0 with friction.law = "
                 "\"critical_load\""},
        BadInput{"LoadNegative",
                 "[cell]\n[friction]\ncritical_load = -1.0\n",
                 {},
                 "test.toml:3: friction.critical_load = -1: must be >= 0"},
        BadInput{"LoadUnderAnotherLaw",
                 "[cell]\n[friction]\nlaw = 'coulomb'\ncritical_load = 2.0\n",
                 {},
                 "test.toml:4: friction.critical_load = 2: means nothing with friction.law = "
                 "\"coulomb\""},
        BadInput{"LoadUnderTheDefaultLaw",
                 "[cell]\n",
                 {"friction.critical_load=2"},
                 "friction.critical_load = 2: means nothing with friction.law = \"stribeck\""},
        BadInput{"LawWord",
                 "[cell]\n",
                 {"friction.law=critical"},
                 "friction.law = \"critical\": must be \"stribeck\", \"coulomb\" or "
                 "\"critical_load\""},
        BadInput{"LawInASediment",
                 "[sediment]\n[friction]\nlaw = 'critical_load'\n",
                 {},
                 "friction.law = \"critical_load\": a sediment's contacts are boundary "
                 "lubricated"},
        BadInput{"LoadInASediment",
                 "[sediment]\n[friction]\nlaw = 'coulomb'\ncritical_load = 1.0\n",
                 {},
                 "friction.critical_load: not a key of a [sediment] run"}),
    [](const ::testing::TestParamInfo<BadInput>& p) { return p.param.name; });

}  // namespace
}  // namespace dilatant::config_critical_load_test
