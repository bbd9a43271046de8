#include "io/config.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "io/input_error.hpp"
#include "io/io_test_files.hpp"

namespace dilatant::config_test {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;

constexpr const char* kScene = R"(# a ball on a floor in a periodic box
[scene]
particles = "inputs/particles.csv"
gravity = [0.0, -1, 0.0]
box = [4.0, 0.0, 5.5]
periodic = [true, false, true]
trajectory_interval = 0.5

[[scene.planes]]
point = [0.0, 0.0, 0.0]
normal = [0.0, 2.0, 0.0]

[[scene.planes]]
point = [0, 3, 0]
normal = [0, -1, 0]

[particles]
density = 2500

[friction]
law = "coulomb"
mu0 = 0.4

[fluid]
eta_f = 1e-3

[solver]
dt = 1e-4
tolerance = 1e-8
max_iterations = 200

[run]
time = 2.0
)";

Config parse(const std::string& text, const std::vector<std::string>& overrides = {}) {
  return parse_config(text, "test.toml", "/base", overrides);
}

TEST(Config, ValidSceneParsesToTheExpectedValues) {
  const auto c = parse(kScene);
  ASSERT_TRUE(c.scene());
  EXPECT_FALSE(c.cell());
  const auto& s = *c.scene();
  EXPECT_EQ(s.particles, std::filesystem::path("/base/inputs/particles.csv"));
  EXPECT_EQ(s.gravity, Vec3(0.0, -1.0, 0.0));
  EXPECT_EQ(s.box, Vec3(4.0, 0.0, 5.5));
  EXPECT_EQ(s.periodic, (std::array<bool, 3>{true, false, true}));
  EXPECT_EQ(s.trajectory_interval, 0.5);
  ASSERT_EQ(s.planes.size(), 2u);
  EXPECT_EQ(s.planes[0].normal, Vec3(0.0, 1.0, 0.0));  // normalised
  EXPECT_EQ(s.planes[1].point, Vec3(0.0, 3.0, 0.0));
  EXPECT_EQ(s.planes[1].normal, Vec3(0.0, -1.0, 0.0));
  EXPECT_EQ(c.density, 2500.0);  // an integer where a float is expected
  EXPECT_EQ(c.friction.law, FrictionLawKind::Coulomb);
  EXPECT_EQ(c.friction.mu0, 0.4);
  EXPECT_EQ(c.friction.s_c, 5e-5);  // defaults for the keys not given
  EXPECT_EQ(c.friction.s_lim, 0.1);
  EXPECT_EQ(c.fluid.eta_f, 1e-3);
  EXPECT_EQ(c.fluid.lambda, 10.0);
  EXPECT_EQ(c.solver.dt, 1e-4);
  EXPECT_EQ(c.solver.tolerance, 1e-8);
  EXPECT_EQ(c.solver.max_iterations, 200);
  EXPECT_EQ(c.run.time, 2.0);
  EXPECT_EQ(c.source, "test.toml");
}

TEST(Config, DefaultsFillInEveryMissingKey) {
  const auto c = parse("[cell]\n");
  ASSERT_TRUE(c.cell());
  EXPECT_FALSE(c.scene());
  const auto& cell = *c.cell();
  EXPECT_EQ(cell.size, Vec3(25.0, 10.0, 27.0));
  EXPECT_EQ(cell.phi, 0.58);
  EXPECT_EQ(cell.radius_min, 0.8);
  EXPECT_EQ(cell.radius_max, 1.0);
  EXPECT_EQ(cell.seed, 1);
  EXPECT_EQ(cell.shear_stress, 1.0);
  EXPECT_EQ(cell.wall_mass, 0.0);
  EXPECT_EQ(c.density, 1.0);
  EXPECT_EQ(c.friction.law, FrictionLawKind::Stribeck);
  EXPECT_EQ(c.friction.mu0, 0.1);
  EXPECT_EQ(c.friction.s_c, 5e-5);
  EXPECT_EQ(c.friction.s_lim, 0.1);
  EXPECT_EQ(c.fluid.lambda, 10.0);
  EXPECT_EQ(c.fluid.eta_f, 0.0);
  EXPECT_EQ(c.solver.dt, 0.0);
  EXPECT_EQ(c.solver.convergence, Convergence::Residual);
  EXPECT_EQ(c.solver.tolerance, 1e-2);
  EXPECT_EQ(c.solver.max_iterations, 1000);
  EXPECT_TRUE(c.notes.empty());
  EXPECT_EQ(c.run.strain, 10.0);
  EXPECT_EQ(c.run.time, 0.0);
  EXPECT_EQ(c.run.transient_strain, 2.0);
  EXPECT_EQ(c.run.output_interval, 0.05);
  // The resolved table holds every key.
  EXPECT_EQ(c.resolved.at_path("cell.phi").value<double>(), 0.58);
  EXPECT_EQ(c.resolved.at_path("solver.max_iterations").value<int64_t>(), 1000);
  EXPECT_EQ(c.resolved.at_path("friction.law").value<std::string>(), "stribeck");
}

TEST(Config, BuiltInDefaultIsThePapersCell) {
  const auto c = default_cell_config();
  EXPECT_EQ(c.source, "<built-in>");
  ASSERT_TRUE(c.cell());
  EXPECT_EQ(c.cell()->phi, 0.58);
  EXPECT_EQ(c.friction.mu0, 0.1);
  EXPECT_EQ(c.friction.s_c, 5e-5);
  EXPECT_EQ(c.friction.law, FrictionLawKind::Stribeck);
  // The literal model, thickened, and a run long enough to be steady.
  EXPECT_EQ(c.fluid.lambda, 100.0);
  EXPECT_EQ(c.fluid.lubrication, LubricationKind::None);
  EXPECT_EQ(c.fluid.drag, DragKind::None);
  EXPECT_EQ(c.run.strain, 12.0);
  EXPECT_EQ(c.run.transient_strain, 6.0);
  const auto changed = default_cell_config({"friction.mu0=0.35", "cell.phi=0.59"});
  EXPECT_EQ(changed.friction.mu0, 0.35);
  EXPECT_EQ(changed.cell()->phi, 0.59);
}

void expect_round_trip(const Config& c) {
  const auto text = resolved_toml(c);
  const auto again = parse_config(text, "config.toml", "/elsewhere", {});
  EXPECT_EQ(again.resolved, c.resolved) << text;
  const auto body = [](const std::string& t) { return t.substr(t.find("\n\n")); };  // no header
  EXPECT_EQ(body(resolved_toml(again)), body(text));
  EXPECT_EQ(again.friction.s_c, c.friction.s_c);
  EXPECT_EQ(again.solver.tolerance, c.solver.tolerance);
  EXPECT_EQ(again.run.output_interval, c.run.output_interval);
  EXPECT_EQ(again.cell() != nullptr, c.cell() != nullptr);
  EXPECT_EQ(again.scene() != nullptr, c.scene() != nullptr);
}

TEST(Config, ResolvedTomlRoundTrips) {
  const auto scene = parse(kScene);
  expect_round_trip(scene);
  const auto again = parse_config(resolved_toml(scene), "config.toml", "/elsewhere", {});
  EXPECT_EQ(again.scene()->particles, scene.scene()->particles);  // absolute: base dir ignored
  EXPECT_EQ(again.scene()->planes.size(), 2u);
  EXPECT_EQ(again.scene()->planes[1].normal, scene.scene()->planes[1].normal);
  EXPECT_EQ(again.scene()->periodic, scene.scene()->periodic);

  expect_round_trip(parse("[cell]\n"));
  // Values without a short decimal form survive exactly too.
  const auto odd = parse("[cell]\nphi = 0.5812345678901234\n[friction]\ns_c = 1.2345e-7\n");
  expect_round_trip(odd);
  expect_round_trip(parse("[scene]\nparticles = 'p.csv'\n[run]\ntime = 1\n"));  // no planes
}

// A resolved config.toml written before solver.convergence existed (0.6)
// keeps the meaning its solver.tolerance had, the relative change, and says
// so in one note; a hand-written file, a new resolved one, or an old one that
// names the test itself, takes what it says, silently.
TEST(Config, AnOlderResolvedConfigKeepsItsToleranceMeaningWithOneNote) {
  const std::string body =
      "\n[cell]\nphi = 0.58\n\n[solver]\ntolerance = 0.0001\nmax_iterations = 1000\n";
  const std::string old_header =
      "# dilatant: resolved configuration of this run (every key, defaults filled in;\n"
      "# keys and units: `dilatant run --help`). Loaded from: cell.toml\n";
  const auto old = parse_config(old_header + body, "out/a/config.toml", "/", {});
  EXPECT_EQ(old.solver.convergence, Convergence::Change);
  EXPECT_EQ(old.solver.tolerance, 1e-4);
  ASSERT_EQ(old.notes.size(), 1u);
  EXPECT_THAT(old.notes[0], HasSubstr("out/a/config.toml was written before solver.convergence"));
  EXPECT_THAT(old.notes[0], HasSubstr("solver.tolerance = 0.0001 keeps its old meaning"));
  EXPECT_EQ(old.notes[0].find('\n'), std::string::npos);
  // Written again, it names the test: read back as the same run, no note.
  const auto again = parse_config(resolved_toml(old), "config.toml", "/", {});
  EXPECT_EQ(again.solver.convergence, Convergence::Change);
  EXPECT_TRUE(again.notes.empty());
  EXPECT_THAT(resolved_toml(parse("[cell]\n")), HasSubstr("convergence = 'residual'"));

  const auto hand_written = parse_config(body, "cell.toml", "/", {});
  EXPECT_EQ(hand_written.solver.convergence, Convergence::Residual);
  EXPECT_TRUE(hand_written.notes.empty());
  const auto chosen =
      parse_config(old_header + body, "config.toml", "/", {"solver.convergence=residual"});
  EXPECT_EQ(chosen.solver.convergence, Convergence::Residual);
  EXPECT_TRUE(chosen.notes.empty());
}

TEST(Config, LoadConfigResolvesParticlesNextToTheFile) {
  test::TempDir dir;
  const auto file = dir.write("setup/scene.toml", kScene);
  const auto c = load_config(file, {});
  EXPECT_EQ(c.scene()->particles, (dir.path() / "setup/inputs/particles.csv").lexically_normal());
  EXPECT_EQ(c.source, file.string());
  const auto message = test::input_error_message(
      [&] { load_config(dir.write("bad.toml", "[cell]\n\n[friction]\nmu0 = -0.1\n"), {}); });
  EXPECT_EQ(message, (dir.path() / "bad.toml").string() + ":4: friction.mu0 = -0.1: must be >= 0");
  EXPECT_THAT(test::input_error_message([&] { load_config(dir.path() / "missing.toml", {}); }),
              HasSubstr("missing.toml: cannot read"));
}

TEST(Config, OverridesSetNumbersArraysStringsAndBareWords) {
  const auto c = parse("[cell]\n[friction]\nmu0 = 0.2\n",
                       {"friction.mu0=0.3", "cell.size=[10.0, 6.0, 12.0]", "run.strain = 20",
                        "friction.law=\"coulomb\"", "solver.max_iterations=50"});
  EXPECT_EQ(c.friction.mu0, 0.3);
  EXPECT_EQ(c.cell()->size, Vec3(10.0, 6.0, 12.0));
  EXPECT_EQ(c.run.strain, 20.0);
  EXPECT_EQ(c.friction.law, FrictionLawKind::Coulomb);
  EXPECT_EQ(c.solver.max_iterations, 50);  // [solver] created by the override

  EXPECT_EQ(parse("[cell]\n", {"friction.law=coulomb"}).friction.law, FrictionLawKind::Coulomb);
  EXPECT_EQ(parse("[cell]\n", {"friction.mu0=0.3", "friction.mu0=0.4"}).friction.mu0, 0.4);

  const auto scene = parse(
      kScene, {"scene.periodic=[false, true, false]", "scene.box=[1, 2, 3]",
               "scene.particles=other.csv", "scene.planes=[{point=[0,0,0], normal=[0,0,3]}]"});
  EXPECT_EQ(scene.scene()->periodic, (std::array<bool, 3>{false, true, false}));
  EXPECT_EQ(scene.scene()->particles, std::filesystem::path("/base/other.csv"));
  ASSERT_EQ(scene.scene()->planes.size(), 1u);
  EXPECT_EQ(scene.scene()->planes[0].normal, Vec3(0.0, 0.0, 1.0));
  // An overridden value shows in the resolved configuration.
  EXPECT_EQ(scene.resolved.at_path("scene.box").as_array()->size(), 3u);
  EXPECT_EQ(scene.resolved.at_path("scene.box[1]").value<double>(), 2.0);
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
}  // namespace dilatant::config_test
