// Bad configs: each one is refused with one line naming the file, the key
// (and line, where TOML gives one) and what is wrong (docs/reliability.md).
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "io/config.hpp"
#include "io/input_error.hpp"
#include "io/io_test_files.hpp"

namespace dilatant::config_bad_input_test {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;

Config parse(const std::string& text, const std::vector<std::string>& overrides = {}) {
  return parse_config(text, "test.toml", "/base", overrides);
}

// A bad input, the overrides to apply, and what its message must contain.
struct BadInput {
  std::string name;
  std::string toml;
  std::vector<std::string> overrides;
  std::vector<std::string> expected;
};

class ConfigBadInput : public ::testing::TestWithParam<BadInput> {};

TEST_P(ConfigBadInput, ThrowsOneLineNamingTheKey) {
  const auto& bad = GetParam();
  const auto message = test::input_error_message([&] { parse(bad.toml, bad.overrides); });
  for (const auto& part : bad.expected) EXPECT_THAT(message, HasSubstr(part));
  EXPECT_THAT(message, Not(HasSubstr("\n")));
}

const std::string kSceneHead = "[scene]\nparticles = 'p.csv'\n[run]\ntime = 1.0\n";

INSTANTIATE_TEST_SUITE_P(
    Config, ConfigBadInput,
    ::testing::Values(
        BadInput{"BothModes", "[cell]\n[scene]\nparticles='p.csv'\n", {}, {"test.toml", "both"}},
        BadInput{"NeitherMode", "[friction]\nmu0 = 0.1\n", {}, {"test.toml", "neither"}},
        BadInput{"InvalidToml", "[cell]\nphi = = 0.5\n", {}, {"test.toml:2:", "invalid TOML"}},
        BadInput{"DuplicateKey", "[cell]\nphi = 0.5\nphi = 0.4\n", {}, {"test.toml:3:"}},
        BadInput{"UnknownSection", "[cell]\n[frictoin]\nmu0 = 0.1\n", {}, {":2: frictoin:"}},
        BadInput{"UnknownTopLevelKey", "density = 2\n[cell]\n", {}, {":1: density: unknown"}},
        BadInput{"UnknownKey", "[cell]\n[friction]\nmu = 0.3\n", {}, {":3: friction.mu: unknown"}},
        BadInput{"UnknownPlaneKey",
                 kSceneHead + "[[scene.planes]]\npoint=[0,0,0]\nnormal=[0,0,1]\noffset=1\n",
                 {},
                 {"scene.planes[0].offset: unknown"}},
        BadInput{"SectionNotATable", "friction = 3\n[cell]\n", {}, {"friction: expected a table"}},
        BadInput{"WrongType",
                 "[cell]\n[friction]\nmu0 = '0.1'\n",
                 {},
                 {"friction.mu0: expected a number, got string"}},
        BadInput{"FloatForInteger",
                 "[cell]\n[solver]\nmax_iterations = 10.5\n",
                 {},
                 {"solver.max_iterations: expected an integer, got float"}},
        BadInput{"SkipOpenContactsNotABoolean",
                 "[cell]\n[solver]\nskip_open_contacts = 1\n",
                 {},
                 {"test.toml:3: solver.skip_open_contacts", "expected a boolean"}},
        BadInput{"NegativeMu0",
                 "[cell]\n[friction]\nmu0 = -0.1\n",
                 {},
                 {"test.toml:3: friction.mu0 = -0.1: must be >= 0"}},
        BadInput{"NanMu0", "[cell]\n[friction]\nmu0 = nan\n", {}, {"friction.mu0", "finite"}},
        BadInput{"InfGravity",
                 kSceneHead,
                 {"scene.gravity=[0, 0, -inf]"},
                 {"scene.gravity[2]", "finite"}},
        BadInput{"ZeroSc", "[cell]\n[friction]\ns_c = 0\n", {}, {"friction.s_c = 0"}},
        BadInput{"ScTooLarge",
                 "[cell]\n[friction]\ns_c = 0.3\ns_lim = 0.31\n",
                 {},
                 {"friction.s_c = 0.3", "5/(6 pi)"}},
        BadInput{"SlimBelowSc",
                 "[cell]\n[friction]\ns_c = 0.01\ns_lim = 0.001\n",
                 {},
                 {"friction.s_lim = 0.001: must be > friction.s_c"}},
        BadInput{"ScAboveDefaultSlim",
                 "[cell]\n",
                 {"friction.s_c=0.2"},
                 {"--set friction.s_c = 0.2: must be < friction.s_lim"}},
        BadInput{"UnknownLaw",
                 "[cell]\n[friction]\nlaw = 'viscous'\n",
                 {},
                 {"friction.law = \"viscous\"", "stribeck"}},
        BadInput{"NegativeEtaF",
                 "[scene]\nparticles = \"p.csv\"\n[run]\ntime = 1.0\n[fluid]\neta_f = -1\n",
                 {},
                 {"fluid.eta_f = -1"}},
        BadInput{"ZeroLambda", "[cell]\n[fluid]\nlambda = 0\n", {}, {"fluid.lambda = 0"}},
        BadInput{
            "ZeroDensity", "[cell]\n[particles]\ndensity = 0.0\n", {}, {"particles.density = 0"}},
        BadInput{"NegativeDt", "[cell]\n[solver]\ndt = -1e-3\n", {}, {"solver.dt = -0.001"}},
        BadInput{"ToleranceOne", "[cell]\n[solver]\ntolerance = 1\n", {}, {"solver.tolerance"}},
        BadInput{"ZeroIterations",
                 "[cell]\n[solver]\nmax_iterations = 0\n",
                 {},
                 {"solver.max_iterations = 0"}},
        BadInput{"NegativeStrain", "[cell]\n[run]\nstrain = -1\n", {}, {"run.strain = -1"}},
        BadInput{"NegativeTime",
                 "[scene]\nparticles = \"p.csv\"\n[run]\ntime = -1\n",
                 {},
                 {"run.time = -1: must be > 0 in scene mode"}},
        BadInput{"TransientNotBelowStrain",
                 "[cell]\n[run]\nstrain = 2\ntransient_strain = 2\n",
                 {},
                 {"run.transient_strain = 2: must be < run.strain"}},
        BadInput{"StrainBelowDefaultTransient",
                 "[cell]\n[run]\nstrain = 1\n",
                 {},
                 {"run.strain = 1: must be > run.transient_strain"}},
        BadInput{"ZeroOutputInterval",
                 "[cell]\n[run]\noutput_interval = 0\n",
                 {},
                 {"run.output_interval = 0"}},
        BadInput{"SceneWithoutTime",
                 "[scene]\nparticles = 'p.csv'\n",
                 {},
                 {"run.time = 0 (default): must be > 0 in scene mode"}},
        BadInput{"PhiTooLarge", "[cell]\nphi = 0.74\n", {}, {"cell.phi = 0.74"}},
        BadInput{"ZeroPhi", "[cell]\nphi = 0\n", {}, {"cell.phi = 0"}},
        BadInput{"ZeroRadiusMin", "[cell]\nradius_min = 0\n", {}, {"cell.radius_min = 0"}},
        BadInput{"RadiusMinAboveMax",
                 "[cell]\nradius_min = 1.2\nradius_max = 1.0\n",
                 {},
                 {"cell.radius_max = 1", "cell.radius_min"}},
        BadInput{"ZeroSize", "[cell]\nsize = [25, 0, 27]\n", {}, {"cell.size = [25, 0, 27]"}},
        BadInput{"ShortSize", "[cell]\nsize = [25, 10]\n", {}, {"cell.size", "3 elements, got 2"}},
        BadInput{"ZeroShearStress", "[cell]\nshear_stress = 0\n", {}, {"cell.shear_stress"}},
        BadInput{"NegativeWallMass", "[cell]\nwall_mass = -1\n", {}, {"cell.wall_mass = -1"}},
        BadInput{"NegativeSeed", "[cell]\nseed = -1\n", {}, {"cell.seed = -1"}},
        BadInput{"MissingParticles",
                 "[scene]\n[run]\ntime = 1\n",
                 {},
                 {"test.toml:1: scene.particles is missing"}},
        BadInput{"ParticlesNotAString",
                 "[scene]\nparticles = 3\n",
                 {},
                 {"scene.particles: expected a string"}},
        BadInput{"NegativeBox", kSceneHead, {"scene.box=[-1, 0, 0]"}, {"--set scene.box"}},
        BadInput{"PeriodicWithoutBox",
                 kSceneHead,
                 {"scene.periodic=[false, true, false]"},
                 {"scene.box = [0, 0, 0] (default)", "axis y is periodic"}},
        BadInput{"PeriodicNotBool",
                 kSceneHead,
                 {"scene.periodic=[1, 0, 0]"},
                 {"scene.periodic[0]: expected a boolean, got integer"}},
        BadInput{"ShortGravity",
                 kSceneHead,
                 {"scene.gravity=[0, -9.81]"},
                 {"scene.gravity", "expected 3 elements"}},
        BadInput{"ZeroTrajectoryInterval",
                 kSceneHead,
                 {"scene.trajectory_interval=0"},
                 {"scene.trajectory_interval"}},
        BadInput{"ZeroNormal",
                 kSceneHead + "[[scene.planes]]\npoint=[0,0,0]\nnormal=[0,0,0]\n",
                 {},
                 {"scene.planes[0].normal", "zero vector"}},
        BadInput{"PlaneWithoutNormal",
                 kSceneHead + "[[scene.planes]]\npoint=[0,0,0]\n",
                 {},
                 {"scene.planes[0].normal is missing"}},
        BadInput{"PlanesNotTables",
                 kSceneHead,
                 {"scene.planes=[1, 2]"},
                 {"scene.planes", "array of tables"}},
        BadInput{"OverrideWithoutEquals",
                 "[cell]\n",
                 {"friction.mu0"},
                 {"--set 'friction.mu0'", "key=value"}},
        BadInput{"OverrideEmptyKey", "[cell]\n", {"=0.3"}, {"--set '=0.3'", "malformed key"}},
        BadInput{"OverrideEmptyKeyPart", "[cell]\n", {"friction..mu0=0.3"}, {"malformed key"}},
        BadInput{"OverrideUnknownKey",
                 "[cell]\n",
                 {"friction.mu=0.3"},
                 {"--set friction.mu: unknown key"}},
        BadInput{"OverrideUnknownSection",
                 "[cell]\n",
                 {"frictoin.mu0=0.3"},
                 {"--set frictoin.mu0: unknown section"}},
        BadInput{"OverrideTooDeep",
                 kSceneHead,
                 {"scene.planes.point=[0,0,0]"},
                 {"--set scene.planes.point"}},
        BadInput{"OverrideBadValue",
                 "[cell]\n",
                 {"friction.mu0=-1"},
                 {"--set friction.mu0 = -1: must be >= 0"}},
        BadInput{"OverrideBareWordForNumber",
                 "[cell]\n",
                 {"friction.mu0=abc"},
                 {"--set friction.mu0: expected a number, got string"}},
        BadInput{"OverrideBareWordLaw",
                 "[cell]\n",
                 {"friction.law=viscous"},
                 {"--set friction.law = \"viscous\""}},
        BadInput{"OverrideIntoNonTable",
                 "friction = 3\n[cell]\n",
                 {"friction.mu0=0.3"},
                 {"--set friction.mu0", "not a table"}},
        BadInput{"OverrideOtherMode", "[cell]\n", {"scene.gravity=[0, 0, -1]"}, {"both"}}),
    [](const ::testing::TestParamInfo<BadInput>& p) { return p.param.name; });

}  // namespace
}  // namespace dilatant::config_bad_input_test
