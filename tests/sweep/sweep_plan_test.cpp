// Reading a sweep file: the grid of its lists, [[points]] tables, --set
// overrides, continuation chains, the resolved sweep.toml, and the one-line
// errors that name file, line, key and point.
#include "sweep/sweep_plan.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "io/io_test_files.hpp"
#include "sweep/tiny_sweep.hpp"

namespace dilatant::sweep::sweep_plan_test {
namespace {

SweepPlan parse(const std::string& text, const std::vector<std::string>& overrides = {}) {
  return parse_sweep(text, "s.toml", ".", overrides);
}

std::string error_of(const std::string& text, const std::vector<std::string>& overrides = {}) {
  return test::input_error_message([&] { parse(text, overrides); });
}

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

TEST(SweepPlan, TheGridRunsOverEveryListWithTheLastKeyOfTheFileFastest) {
  const SweepPlan plan =
      parse(test::kTinyCell + "[friction]\nmu0 = [0.1, 0.2]\n[fluid]\nlambda = [1, 10.0, 100]\n");
  EXPECT_EQ(plan.keys, (std::vector<std::string>{"friction.mu0", "fluid.lambda"}));
  ASSERT_EQ(plan.points.size(), 6u);
  const double mu0[] = {0.1, 0.1, 0.1, 0.2, 0.2, 0.2};
  const double lambda[] = {1, 10, 100, 1, 10, 100};
  for (std::size_t k = 0; k < 6; ++k) {
    const SweepPoint& p = plan.points[k];
    EXPECT_EQ(p.index, k);
    EXPECT_EQ(p.config.friction.mu0, mu0[k]);
    EXPECT_EQ(p.config.fluid.lambda, lambda[k]);
    EXPECT_EQ(p.config.cell()->phi, 0.58);  // the shared keys as in the file
    EXPECT_EQ(p.config.run.strain, 0.3);
    EXPECT_FALSE(p.continues_from);
  }
  EXPECT_EQ(plan.points[0].label, "mu0=0.1_lambda=1");
  EXPECT_EQ(plan.points[0].folder, "points/000-mu0=0.1_lambda=1");
  EXPECT_EQ(plan.points[5].folder, "points/005-mu0=0.2_lambda=100");
  EXPECT_EQ(plan.points[4].values, (std::vector<std::string>{"0.2", "10.0"}));
  // The list written first varies slowest, wherever its section is.
  const SweepPlan reversed =
      parse(test::kTinyCell + "[fluid]\nlambda = [1.0, 2.0]\n[friction]\nmu0 = [0.1, 0.2]\n");
  EXPECT_EQ(reversed.keys, (std::vector<std::string>{"fluid.lambda", "friction.mu0"}));
  EXPECT_EQ(reversed.points[1].config.friction.mu0, 0.2);
  EXPECT_EQ(reversed.points[1].config.fluid.lambda, 1.0);
}

TEST(SweepPlan, NoListIsASweepOfOnePoint) {
  const SweepPlan plan = parse(test::kTinyCell);
  EXPECT_TRUE(plan.keys.empty());
  ASSERT_EQ(plan.points.size(), 1u);
  EXPECT_EQ(plan.points[0].folder, "points/000-point");
}

TEST(SweepPlan, AnArrayKeyIsSweptOnlyByAListOfArrays) {
  const std::string text = R"([cell]
size = [[6.0, 5.0, 7.0], [8, 6, 9]]
seed = [1, 2]
[friction]
law = ["stribeck", "coulomb"]
)";
  const SweepPlan plan = parse(text);
  EXPECT_EQ(plan.keys, (std::vector<std::string>{"cell.size", "cell.seed", "friction.law"}));
  ASSERT_EQ(plan.points.size(), 8u);
  EXPECT_EQ(plan.points[7].config.cell()->size, Vec3(8, 6, 9));
  EXPECT_EQ(plan.points[7].config.friction.law, FrictionLawKind::Coulomb);
  EXPECT_EQ(plan.points[7].label, "size=8x6x9_seed=2_law=coulomb");
  EXPECT_EQ(plan.points[7].values[0], "[8.0, 6.0, 9.0]");
  // One array is the value itself, not a sweep.
  EXPECT_EQ(parse(test::kTinyCell).points[0].config.cell()->size, Vec3(6, 5, 7));
}

TEST(SweepPlan, PointsTablesListPointsAndMayHoldSmallGrids) {
  const std::string text = test::kTinyCell + R"(
[fluid]
lambda = [1.0, 10.0]

[[points]]
friction.mu0 = [0.1, 0.3]

[[points]]
[points.cell]
phi = 0.55
[points.friction]
mu0 = 0.3
law = "coulomb"
)";
  const SweepPlan plan = parse(text);
  EXPECT_EQ(plan.keys,
            (std::vector<std::string>{"fluid.lambda", "friction.mu0", "cell.phi", "friction.law"}));
  ASSERT_EQ(plan.points.size(), 6u);  // 2 x 2, then 2
  EXPECT_EQ(plan.points[1].config.friction.mu0, 0.3);
  EXPECT_EQ(plan.points[1].config.fluid.lambda, 1.0);
  EXPECT_EQ(plan.points[1].config.cell()->phi, 0.58);
  EXPECT_EQ(plan.points[5].config.cell()->phi, 0.55);
  EXPECT_EQ(plan.points[5].config.fluid.lambda, 10.0);
  EXPECT_EQ(plan.points[5].config.friction.law, FrictionLawKind::Coulomb);
  // Keys a point does not set keep the file's value in its label and row.
  EXPECT_EQ(plan.points[0].label, "lambda=1_mu0=0.1_phi=0.58_law=stribeck");
}

TEST(SweepPlan, OverridesSweepKeysSetSettingsAndWinOverPointsTables) {
  const std::string text = test::kTinyCell +
                           "[[points]]\ncell.phi = 0.55\n[[points]]\n"
                           "cell.phi = 0.56\nfriction.mu0 = 0.2\n";
  const SweepPlan plan = parse(text, {"fluid.lambda=[3.0, 30.0]", "cell.phi=0.5", "sweep.jobs=3"});
  EXPECT_EQ(plan.settings.jobs, 3);
  ASSERT_EQ(plan.points.size(), 4u);
  for (const auto& p : plan.points) EXPECT_EQ(p.config.cell()->phi, 0.5);
  EXPECT_EQ(plan.points[3].config.friction.mu0, 0.2);
  EXPECT_EQ(plan.points[3].config.fluid.lambda, 30.0);
  EXPECT_EQ(plan.keys.back(), "fluid.lambda");  // overrides come after the file's keys
}

TEST(SweepPlan, ContinuationChainsEachCurveInIncreasingLambda) {
  const std::string text = test::kTinyCell + R"(
[friction]
mu0 = [0.1, 0.3]
[fluid]
lambda = [30.0, 3.0, 10.0]
[sweep]
continuation = true
continuation_strain = 0.2
continuation_transient_strain = 0.05
)";
  const SweepPlan plan = parse(text);
  ASSERT_EQ(plan.points.size(), 6u);
  // Curve mu0 0.1: points 0 (30), 1 (3), 2 (10): 1 starts cold, then 2, then 0.
  EXPECT_FALSE(plan.points[1].continues_from);
  EXPECT_EQ(plan.points[2].continues_from, 1u);
  EXPECT_EQ(plan.points[0].continues_from, 2u);
  EXPECT_EQ(plan.points[3].continues_from, 5u);  // mu0 0.3 on its own
  EXPECT_EQ(plan.points[1].config.run.strain, 0.3);
  EXPECT_EQ(plan.points[0].config.run.strain, 0.2);
  EXPECT_EQ(plan.points[0].config.run.transient_strain, 0.05);
  EXPECT_EQ(plan.points[0].config.resolved["run"]["strain"].value<double>(), 0.2);
  const std::string no_lambda = test::kTinyCell +
                                "[friction]\nmu0 = [0.1, 0.3]\n"
                                "[sweep]\ncontinuation = true\n";
  EXPECT_TRUE(contains(error_of(no_lambda), "fluid.lambda is not swept")) << error_of(no_lambda);
}

TEST(SweepPlan, TheResolvedSweepReadsBackAsTheSameSweep) {
  const std::string text = test::kTinyCell + R"(
[fluid]
lambda = [30.0, 3.0]
[[points]]
friction.mu0 = 0.1
[[points]]
cell.size = [[8.0, 6.0, 9.0]]
friction.law = "coulomb"
[sweep]
continuation = true
continuation_strain = 0.2
)";
  const SweepPlan plan = parse(text);
  const SweepPlan again = parse_sweep(resolved_sweep_toml(plan), "sweep.toml", ".", {});
  EXPECT_EQ(again.keys, plan.keys);
  ASSERT_EQ(again.points.size(), plan.points.size());
  for (std::size_t k = 0; k < plan.points.size(); ++k) {
    EXPECT_EQ(again.points[k].folder, plan.points[k].folder);
    EXPECT_EQ(again.points[k].values, plan.points[k].values);
    EXPECT_EQ(again.points[k].continues_from, plan.points[k].continues_from);
    EXPECT_EQ(to_toml(again.points[k].config), to_toml(plan.points[k].config)) << k;
  }
  EXPECT_EQ(again.settings.continuation_strain, 0.2);
}

TEST(SweepPlan, ErrorsNameTheFileTheLineTheKeyAndThePoint) {
  // A bad value inside a list: its line, the key, the point.
  const std::string bad_mu0 = test::kTinyCell + "[friction]\nmu0 = [0.1, -0.2]\n";
  const std::string m = error_of(bad_mu0);
  EXPECT_TRUE(contains(m, "s.toml:14: friction.mu0 = -0.2: must be >= 0")) << m;
  EXPECT_TRUE(contains(m, "(point 1: friction.mu0 = -0.2)")) << m;
  // Inside a [[points]] table.
  const std::string in_points = test::kTinyCell +
                                "[[points]]\ncell.phi = 0.5\n[[points]]\n"
                                "cell.phi = 0.8\n";
  EXPECT_TRUE(contains(error_of(in_points), "s.toml:16: cell.phi = 0.8: must be in (0, 0.74)"))
      << error_of(in_points);
  struct Case {
    std::string text, expected;
  };
  const std::vector<Case> cases = {
      {test::kTinyCell + "[friction]\nmu0 = []\n", "s.toml:14: friction.mu0 = []: an empty list"},
      {test::kTinyCell + "[friction]\nmuu = [0.1, 0.2]\n", "friction.muu: unknown key"},
      {test::kTinyCell + "[sweep]\njobz = 2\n", "s.toml:14: sweep.jobz: unknown key"},
      {test::kTinyCell + "[sweep]\njobs = -1\n", "sweep.jobs = -1: must be in [0, 4096]"},
      {test::kTinyCell + "[sweep]\ncontinuation_strain = 1.0\n",
       "sweep.continuation_strain: applies to continued points only"},
      {test::kTinyCell + "[friction]\nmu0 = [0.1, 0.1]\n",
       "s.toml: points 0 and 1 are the same run"},
      {test::kTinyCell + "[[points]]\nmu0 = 0.1\n", "points.mu0: expected keys of a section"},
      {"points = 3\n" + test::kTinyCell,
       "s.toml:1: points: expected one or more [[points]] tables"},
      {"[scene]\nparticles = \"p.csv\"\n", "sweeps run the shear cell"},
      {test::kTinyCell + "[fluid\n", "s.toml:13:7: invalid TOML"},
  };
  for (const auto& c : cases) {
    const std::string message = error_of(c.text);
    EXPECT_TRUE(contains(message, c.expected)) << message << "\n  expected: " << c.expected;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  }
  EXPECT_TRUE(contains(error_of(test::kTinyCell, {"fluid.lambda=[]"}), "--set fluid.lambda"));
  const std::string strain = error_of(test::kTinyCell, {"run.strain=[0.3, 0.05]"});
  EXPECT_TRUE(contains(strain,
                       "s.toml:11: run.transient_strain = 0.1: must be < run.strain = 0.05 "
                       "(point 1: run.strain = 0.05)"))
      << strain;
}

}  // namespace
}  // namespace dilatant::sweep::sweep_plan_test
