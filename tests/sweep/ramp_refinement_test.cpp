// A refinement of a ramp (sweep.refines, sweep_plan.hpp): extra stresses of a
// finished ramp, each starting from the ramp's final state at the nearest
// lower lambda. The engine is deterministic on one thread, so a refinement's
// point is the very run a ramp through those two lambdas makes; what it
// cannot start from waits, is skipped above a jam, or is refused by name.
#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <sstream>
#include <string>

#include "analysis/delimited_text.hpp"
#include "app/cli_runner.hpp"
#include "io/atomic_file.hpp"
#include "io/input_error.hpp"
#include "sweep/sweep_runner.hpp"
#include "sweep/table_row.hpp"
#include "sweep/tiny_sweep.hpp"

namespace dilatant::sweep::ramp_refinement_test {
namespace {

namespace fs = std::filesystem;

const std::string kRampSettings = R"(
[sweep]
continuation = true
continuation_strain = 0.2
continuation_transient_strain = 0.05
)";

// A ramp of the tiny cell at these lambdas.
std::string ramp(const std::string& lambdas) {
  return test::kTinyCell + "\n[fluid]\nlambda = " + lambdas + "\n" + kRampSettings;
}

// The same cell refining the sweep in `refined` at these lambdas.
std::string refinement(const std::string& lambdas, const fs::path& refined) {
  return ramp(lambdas) + "refines = \"" + refined.generic_string() + "\"\n";
}

std::map<std::string, std::string> row(const fs::path& table, std::size_t k) {
  return test::table_row(table, k);
}

SweepOutcome run(const SweepPlan& plan, const fs::path& out) {
  SweepRunOptions o;
  o.out = out;
  o.jobs = 2;
  return run_sweep(plan, o);
}

std::string refusal(const std::string& text, const fs::path& base) {
  try {
    parse_sweep(text, "refine.toml", base, {});
  } catch (const InputError& e) {
    return e.what();
  }
  return "(accepted)";
}

TEST(RampRefinement, EachPointIsTheRunARampThroughTheNearestLowerLambdaMakes) {
  test::TempDir dir;
  const fs::path refined = dir.path() / "ramp";
  const SweepPlan ramp_plan = parse_sweep(ramp("[3.0, 30.0]"), "ramp.toml", ".", {});
  ASSERT_EQ(run(ramp_plan, refined).done, 2u);

  const SweepPlan plan =
      parse_sweep(refinement("[10.0, 5.0, 100.0]", refined), "refine.toml", ".", {});
  const fs::path out = dir.path() / "refine";
  const SweepOutcome outcome = run(plan, out);
  EXPECT_EQ(outcome.done, 3u);
  const fs::path table = out / "flowcurves.csv";
  auto at10 = row(table, 0), at5 = row(table, 1), at100 = row(table, 2);
  const auto from = [&](std::size_t k) {
    return fs::proximate(refined / ramp_plan.points[k].folder).string();
  };
  EXPECT_EQ(at10["start"], from(0));  // lambda 3: the nearest lower
  EXPECT_EQ(at5["start"], from(0));
  EXPECT_EQ(at100["start"], from(1));                 // lambda 30: above the ramp's last point too
  EXPECT_NEAR(std::stod(at10["strain"]), 0.2, 0.02);  // a continued point's strain

  // The ramp 3 -> 10 of the same cell: its second point is the refinement's.
  const SweepPlan direct = parse_sweep(ramp("[3.0, 10.0]"), "direct.toml", ".", {});
  run(direct, dir.path() / "direct");
  auto same = row(dir.path() / "direct" / "flowcurves.csv", 1);
  for (const char* c : {"gamma_dot", "shear_stress", "frac_bl", "phi_bulk", "steps", "strain"})
    EXPECT_EQ(at10[c], same[c]) << c;

  // The resolved sweep reads back as the same refinement (and resumes).
  const SweepPlan again = load_sweep(out / "sweep.toml", {});
  ASSERT_EQ(again.points.size(), 3u);
  for (std::size_t k = 0; k < 3; ++k) {
    ASSERT_TRUE(again.points[k].refines);
    EXPECT_EQ(again.points[k].refines->ramp, plan.points[k].refines->ramp);
    EXPECT_EQ(again.points[k].config.resolved, plan.points[k].config.resolved);
  }
  EXPECT_EQ(run(again, out).skipped, 3u);
}

TEST(RampRefinement, WaitsForTheRampAndSkipsWhatLiesAboveItsJam) {
  test::TempDir dir;
  const fs::path refined = dir.path() / "ramp";
  const SweepPlan ramp_plan = parse_sweep(ramp("[3.0, 30.0]"), "ramp.toml", ".", {});
  run(ramp_plan, refined);
  const fs::path top = refined / ramp_plan.points[1].folder / "summary.json";
  const std::string top_summary = test::read_text(top);
  fs::remove(top);  // the ramp's lambda 30 has not finished

  const SweepPlan plan = parse_sweep(refinement("[10.0, 100.0]", refined), "r.toml", ".", {});
  const fs::path out = dir.path() / "refine";
  SweepOutcome outcome = run(plan, out);
  EXPECT_EQ(outcome.done, 1u);
  EXPECT_EQ(outcome.pending, 1u);  // lambda 100 waits for the ramp's lambda 30
  EXPECT_EQ(row(out / "flowcurves.csv", 1)["status"], "pending");

  // The ramp's lambda 30 is there now, but the ramp jammed at lambda 3.
  write_file_atomically(top, top_summary);
  const fs::path bottom = refined / ramp_plan.points[0].folder / "summary.json";
  auto summary = nlohmann::json::parse(test::read_text(bottom));
  summary["jammed"] = true;
  write_file_atomically(bottom, summary.dump());
  outcome = run(plan, out);
  EXPECT_EQ(outcome.done, 1u);  // lambda 10 was done before
  EXPECT_EQ(outcome.above_jam, 1u);
  auto above = row(out / "flowcurves.csv", 1);
  EXPECT_EQ(above["status"], "skipped");
  EXPECT_NE(above["error"].find("the refined ramp jammed at"), std::string::npos) << above["error"];
}

TEST(RampRefinement, APointItCannotPlaceIsRefusedByName) {
  test::TempDir dir;
  const fs::path refined = dir.path() / "ramp";
  fs::create_directories(refined);
  const SweepPlan ramp_plan = parse_sweep(ramp("[3.0, 30.0]"), "ramp.toml", ".", {});
  write_file_atomically(refined / "sweep.toml", resolved_sweep_toml(ramp_plan));
  // The file's folder is the base of a relative sweep.refines.
  EXPECT_EQ(refusal(refinement("[10.0]", "ramp"), dir.path()), "(accepted)");

  const auto refused = [&](const std::string& text, const std::string& what) {
    const std::string message = refusal(text, ".");
    EXPECT_NE(message.find(what), std::string::npos) << message;
    EXPECT_EQ(message.rfind("refine.toml", 0), 0u) << message;
  };
  refused(refinement("[3.0, 10.0]", refined), "lambda 3 is a point of the refined ramp already");
  refused(refinement("[1.0]", refined), "lambda 1 is below its ramp's first point (lambda 3)");
  refused(refinement("[10.0]", refined) + "[friction]\ns_c = 1e-4\n",
          "matches no ramp of " + refined.string() + " (the closest differs in friction.s_c)");
  refused(refinement("[10.0]", dir.path() / "nowhere"), "sweep.refines = ");
  refused(test::kTinyCell + "[fluid]\nlambda = [10.0]\n[sweep]\nrefines = \"" +
              refined.generic_string() + "\"\n",
          "sweep.refines: applies to continued points only");

  // Only a ramp can be refined.
  const fs::path grid = dir.path() / "grid";
  fs::create_directories(grid);
  write_file_atomically(grid / "sweep.toml",
                        resolved_sweep_toml(parse_sweep(test::kTinyGrid, "g.toml", ".", {})));
  refused(refinement("[10.0]", grid), "not a ramp sweep (no continuation)");
}

}  // namespace
}  // namespace dilatant::sweep::ramp_refinement_test
