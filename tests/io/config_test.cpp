#include "io/config.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "io/input_error.hpp"
#include "io/io_test_files.hpp"

namespace dilatant::config_test {
namespace {

using ::testing::HasSubstr;

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

}  // namespace
}  // namespace dilatant::config_test
