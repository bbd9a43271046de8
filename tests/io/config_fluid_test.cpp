// The keys of the fluid forces and of the volume-fraction definition: their
// defaults (the literal model), their values, and bad input naming the key.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "io/config.hpp"
#include "io/input_error.hpp"
#include "io/io_test_files.hpp"

namespace dilatant::config_fluid_test {
namespace {

using ::testing::HasSubstr;

Config parse(const std::string& text, const std::vector<std::string>& overrides = {}) {
  return parse_config(text, "test.toml", "/base", overrides);
}

const std::string kScene = "[scene]\nparticles = 'p.csv'\n[run]\ntime = 1.0\n";

TEST(ConfigFluid, DefaultsAreTheLiteralModel) {
  const Config c = parse("[cell]\n");
  EXPECT_EQ(c.fluid.lubrication, LubricationKind::None);
  EXPECT_EQ(c.fluid.drag, DragKind::None);
  EXPECT_FALSE(c.friction.viscous_beyond_s_lim);
  EXPECT_EQ(c.cell()->phi_definition, PhiDefinition::BetweenWalls);
  EXPECT_EQ(c.resolved.at_path("fluid.lubrication").value<std::string>(), "none");
  EXPECT_EQ(c.resolved.at_path("fluid.drag").value<std::string>(), "none");
  // A dry scene (no eta_f) has no fluid forces, and needs no key to say so.
  EXPECT_NO_THROW(parse(kScene));
  EXPECT_EQ(c.resolved.at_path("friction.beyond_s_lim").value<std::string>(), "cap");
  EXPECT_EQ(c.resolved.at_path("cell.phi_definition").value<std::string>(), "between-walls");
}

TEST(ConfigFluid, EveryKeyReadsAndRoundTrips) {
  const Config c = parse(
      "[cell]\nphi_definition = 'box'\n[friction]\nbeyond_s_lim = 'viscous'\n[fluid]\n"
      "lubrication = 'normal'\nlubrication_cutoff = 0.25\nlubrication_regularization = 1e-2\n"
      "drag = 'stokes'\n");
  EXPECT_EQ(c.fluid.lubrication, LubricationKind::Normal);
  EXPECT_EQ(c.fluid.drag, DragKind::Stokes);
  EXPECT_EQ(c.fluid.lubrication_cutoff, 0.25);
  EXPECT_EQ(c.fluid.lubrication_regularization, 1e-2);
  EXPECT_TRUE(c.friction.viscous_beyond_s_lim);
  EXPECT_EQ(c.cell()->phi_definition, PhiDefinition::Box);
  const Config again = parse(resolved_toml(c));
  EXPECT_EQ(again.fluid.drag, DragKind::Stokes);
  EXPECT_EQ(again.fluid.lubrication_cutoff, 0.25);
  EXPECT_TRUE(again.friction.viscous_beyond_s_lim);
  EXPECT_EQ(again.cell()->phi_definition, PhiDefinition::Box);
  // The same keys in a scene, with a viscosity.
  const Config scene = parse(kScene + "[fluid]\neta_f = 1e-3\ndrag = 'stokes'\n");
  EXPECT_EQ(scene.fluid.drag, DragKind::Stokes);
}

struct BadFluidInput {
  std::string name;
  std::string toml;
  std::vector<std::string> overrides;
  std::string expected;
};

void PrintTo(const BadFluidInput& bad, std::ostream* os) { *os << bad.name; }

class ConfigFluidBadInput : public ::testing::TestWithParam<BadFluidInput> {};

TEST_P(ConfigFluidBadInput, ThrowsOneLineNamingTheKey) {
  const auto& bad = GetParam();
  const auto message = test::input_error_message([&] { parse(bad.toml, bad.overrides); });
  EXPECT_THAT(message, HasSubstr(bad.expected));
  EXPECT_THAT(message, ::testing::Not(HasSubstr("\n")));
}

INSTANTIATE_TEST_SUITE_P(
    Config, ConfigFluidBadInput,
    ::testing::Values(
        BadFluidInput{"LubricationWord",
                      "[cell]\n[fluid]\nlubrication = 'full'\n",
                      {},
                      "test.toml:3: fluid.lubrication = \"full\": must be \"none\" or \"normal\""},
        BadFluidInput{"DragWord",
                      "[cell]\n",
                      {"fluid.drag=oseen"},
                      "fluid.drag = \"oseen\": must be \"none\" or \"stokes\""},
        BadFluidInput{
            "DragNotAString", "[cell]\n[fluid]\ndrag = 1\n", {}, "fluid.drag: expected a string"},
        BadFluidInput{"CutoffZero",
                      "[cell]\n",
                      {"fluid.lubrication_cutoff=0"},
                      "fluid.lubrication_cutoff = 0: must be > 0"},
        BadFluidInput{"RegularizationNegative",
                      "[cell]\n[fluid]\nlubrication_regularization = -1e-3\n",
                      {},
                      "fluid.lubrication_regularization = -0.001: must be > 0"},
        BadFluidInput{"BeyondSlimWord",
                      "[cell]\n",
                      {"friction.beyond_s_lim=linear"},
                      "friction.beyond_s_lim = \"linear\": must be \"cap\" or \"viscous\""},
        BadFluidInput{"PhiDefinitionWord",
                      "[cell]\nphi_definition = 'bulk'\n",
                      {},
                      "cell.phi_definition = \"bulk\": must be \"between-walls\" or \"box\""},
        BadFluidInput{"PhiDefinitionInAScene",
                      kScene + "phi_definition = 'box'\n",
                      {},
                      "run.phi_definition: unknown key"},
        BadFluidInput{"SceneDragWithoutViscosity",
                      kScene + "[fluid]\ndrag = 'stokes'\n",
                      {},
                      "fluid.drag = \"stokes\": needs fluid.eta_f > 0"},
        BadFluidInput{"SceneFilmWithoutViscosity",
                      kScene + "[fluid]\nlubrication = 'normal'\n",
                      {},
                      "fluid.lubrication = \"normal\": needs fluid.eta_f > 0"}),
    [](const ::testing::TestParamInfo<BadFluidInput>& p) { return p.param.name; });

}  // namespace
}  // namespace dilatant::config_fluid_test
