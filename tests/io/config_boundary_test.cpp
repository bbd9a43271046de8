// The keys of the cell's boundary and control (docs/shear-cell.md "The
// Lees–Edwards cell"): their defaults, a valid Lees–Edwards cell, and every
// bad combination as one line naming the key (exit 2 from the CLI).
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "io/config.hpp"
#include "io/input_error.hpp"
#include "io/io_test_files.hpp"

namespace dilatant::config_boundary_test {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;

Config parse(const std::string& text, const std::vector<std::string>& overrides = {}) {
  return parse_config(text, "test.toml", "/base", overrides);
}

TEST(ConfigBoundary, DefaultsToTheStressControlledWallCell) {
  const CellConfig cell = *parse("[cell]\n").cell();
  EXPECT_EQ(cell.boundary, CellBoundary::Walls);
  EXPECT_EQ(cell.control, ShearControl::Stress);
  EXPECT_EQ(cell.shear_rate, 0.0);
  EXPECT_EQ(cell.boundary_mass, 0.0);
}

TEST(ConfigBoundary, ReadsALeesEdwardsCellUnderEitherControl) {
  const Config stress = parse("[cell]\nboundary = \"lees-edwards\"\nboundary_mass = 12.5\n");
  EXPECT_EQ(stress.cell()->boundary, CellBoundary::LeesEdwards);
  EXPECT_EQ(stress.cell()->boundary_mass, 12.5);
  const Config rate =
      parse("[cell]\nboundary = \"lees-edwards\"\n", {"cell.control=rate", "cell.shear_rate=0.02"});
  EXPECT_EQ(rate.cell()->control, ShearControl::Rate);
  EXPECT_EQ(rate.cell()->shear_rate, 0.02);
  // The resolved config names them (a resumed run compares it).
  EXPECT_EQ(rate.resolved["cell"]["boundary"].value<std::string>(), "lees-edwards");
  EXPECT_EQ(rate.resolved["cell"]["control"].value<std::string>(), "rate");
  // ... and it loads back: the wall keys it lists sit at their defaults
  // (meaning nothing), which is allowed; other values are errors (below).
  EXPECT_EQ(parse_config(resolved_toml(rate), "config.toml", "/x", {}).resolved, rate.resolved);
  EXPECT_EQ(parse_config(resolved_toml(stress), "config.toml", "/x", {}).resolved, stress.resolved);
}

// Pressure control: the rate and the normal stress imposed, the box height's
// mass in cell.boundary_mass; the resolved config loads back.
TEST(ConfigBoundary, ReadsAPressureControlledLeesEdwardsCell) {
  const Config c =
      parse("[cell]\nboundary = \"lees-edwards\"\ncontrol = \"pressure\"\n",
            {"cell.shear_rate=0.05", "cell.normal_stress=2.5", "cell.boundary_mass=7"});
  EXPECT_EQ(c.cell()->control, ShearControl::Pressure);
  EXPECT_EQ(c.cell()->shear_rate, 0.05);
  EXPECT_EQ(c.cell()->normal_stress, 2.5);
  EXPECT_EQ(c.cell()->boundary_mass, 7.0);
  EXPECT_EQ(c.resolved["cell"]["control"].value<std::string>(), "pressure");
  EXPECT_EQ(parse_config(resolved_toml(c), "config.toml", "/x", {}).resolved, c.resolved);
}

struct BadInput {
  std::string name;
  std::string toml;
  std::vector<std::string> overrides;
  std::vector<std::string> expected;
};

class ConfigBoundaryBadInput : public ::testing::TestWithParam<BadInput> {};

TEST_P(ConfigBoundaryBadInput, ThrowsOneLineNamingTheKey) {
  const auto& bad = GetParam();
  const auto message = test::input_error_message([&] { parse(bad.toml, bad.overrides); });
  for (const auto& part : bad.expected) EXPECT_THAT(message, HasSubstr(part));
  EXPECT_THAT(message, Not(HasSubstr("\n")));
}

INSTANTIATE_TEST_SUITE_P(
    Config, ConfigBoundaryBadInput,
    ::testing::Values(
        BadInput{"UnknownBoundary",
                 "[cell]\nboundary = \"periodic\"\n",
                 {},
                 {"cell.boundary", "must be \"walls\" or \"lees-edwards\""}},
        BadInput{"UnknownControl",
                 "[cell]\ncontrol = \"strain\"\n",
                 {},
                 {"cell.control", "must be \"stress\", \"rate\" or \"pressure\""}},
        BadInput{"PressureControlWithWalls",
                 "[cell]\ncontrol = \"pressure\"\nshear_rate = 0.1\nnormal_stress = 1\n",
                 {},
                 {"cell.control", "needs cell.boundary = \"lees-edwards\""}},
        BadInput{"PressureControlWithoutRate",
                 "[cell]\nboundary = \"lees-edwards\"\ncontrol = \"pressure\"\nnormal_stress = 1\n",
                 {},
                 {"cell.shear_rate = 0", "must be > 0 under cell.control = \"pressure\""}},
        BadInput{"PressureControlWithoutNormalStress",
                 "[cell]\nboundary = \"lees-edwards\"\ncontrol = \"pressure\"\nshear_rate = 0.1\n",
                 {},
                 {"cell.normal_stress = 0", "must be > 0 under cell.control = \"pressure\""}},
        BadInput{"NegativeNormalStress",
                 "[cell]\nboundary = \"lees-edwards\"\ncontrol = \"pressure\"\nshear_rate = "
                 "0.1\nnormal_stress = -1\n",
                 {},
                 {"cell.normal_stress = -1"}},
        BadInput{"NormalStressUnderRateControl",
                 "[cell]\nboundary = \"lees-edwards\"\ncontrol = \"rate\"\nshear_rate = "
                 "0.1\nnormal_stress = 2\n",
                 {},
                 {"cell.normal_stress = 2", "only under cell.control = \"pressure\""}},
        BadInput{"NormalStressUnderStressControl",
                 "[cell]\nnormal_stress = 2\n",
                 {},
                 {"cell.normal_stress = 2", "only under cell.control = \"pressure\""}},
        BadInput{"RateControlWithWalls",
                 "[cell]\ncontrol = \"rate\"\nshear_rate = 0.1\n",
                 {},
                 {"cell.control", "needs cell.boundary = \"lees-edwards\""}},
        BadInput{"RateControlWithoutRate",
                 "[cell]\nboundary = \"lees-edwards\"\ncontrol = \"rate\"\n",
                 {},
                 {"cell.shear_rate = 0", "must be > 0 under cell.control = \"rate\""}},
        BadInput{"ShearRateUnderStressControl",
                 "[cell]\nboundary = \"lees-edwards\"\nshear_rate = 0.1\n",
                 {},
                 {"cell.shear_rate = 0.1", "only under cell.control = \"rate\""}},
        BadInput{"NegativeShearRate",
                 "[cell]\nboundary = \"lees-edwards\"\ncontrol = \"rate\"\nshear_rate = -1\n",
                 {},
                 {"cell.shear_rate = -1"}},
        BadInput{"WallFrictionWithoutWalls",
                 "[cell]\nboundary = \"lees-edwards\"\nwall_friction = 0.5\n",
                 {},
                 {"cell.wall_friction = 0.5", "means nothing without walls"}},
        BadInput{"WallMassWithoutWalls",
                 "[cell]\nboundary = \"lees-edwards\"\n",
                 {"cell.wall_mass=3"},
                 {"cell.wall_mass = 3", "means nothing without walls"}},
        BadInput{"PhiDefinitionWithoutWalls",
                 "[cell]\nboundary = \"lees-edwards\"\nphi_definition = \"box\"\n",
                 {},
                 {"cell.phi_definition", "means nothing without walls"}},
        BadInput{"BoundaryMassWithWalls",
                 "[cell]\nboundary_mass = 10\n",
                 {},
                 {"cell.boundary_mass = 10", "cell.wall_mass"}},
        BadInput{"BoundaryMassUnderRateControl",
                 "[cell]\nboundary = \"lees-edwards\"\ncontrol = \"rate\"\nshear_rate = "
                 "0.1\nboundary_mass = 10\n",
                 {},
                 {"cell.boundary_mass = 10", "under cell.control = \"rate\""}},
        BadInput{"LeesEdwardsBoxTooLow",
                 "[cell]\nboundary = \"lees-edwards\"\nsize = [8, 8, 3]\n",
                 {},
                 {"cell.size = [8, 8, 3]", "Lz must be at least 4 largest radii"}}),
    [](const ::testing::TestParamInfo<BadInput>& p) { return p.param.name; });

}  // namespace
}  // namespace dilatant::config_boundary_test
