// A refinement of a ramp (sweep.refines, sweep_plan.hpp): extra stresses of a
// ramp; the extra points between two of the ramp's points are a short ramp
// from the ramp's state at the lower one. The engine is deterministic on one
// thread, so a refinement's point is the very run a ramp through those lambdas
// makes; what it cannot start from waits, is skipped above a jam, fails with
// its ramp, or is refused by name.
#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <sstream>
#include <string>

#include "analysis/delimited_text.hpp"
#include "app/cli_runner.hpp"
#include "io/atomic_file.hpp"
#include "io/input_error.hpp"
#include "sweep/cold_start_choice.hpp"
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

using test::table_row;

// The tiny ramp at lambda 3 and 30, planned in `folder` (its sweep.toml) but not run.
SweepPlan planned_ramp(const fs::path& folder) {
  fs::create_directories(folder);
  SweepPlan plan = parse_sweep(ramp("[3.0, 30.0]"), "ramp.toml", ".", {});
  write_file_atomically(folder / "sweep.toml", resolved_sweep_toml(plan));
  return plan;
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

TEST(RampRefinement, EachSegmentIsTheRampThroughItsLambdasFromTheRampsStateBelow) {
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
  auto at10 = table_row(table, 0), at5 = table_row(table, 1), at100 = table_row(table, 2);
  // 5 and 10 lie between the ramp's 3 and 30: 5 starts from 3, 10 from 5;
  // 100 lies above the ramp's last point and starts from it.
  EXPECT_EQ(at5["start"], "../ramp/" + ramp_plan.points[0].folder);
  EXPECT_EQ(at10["start"], plan.points[1].folder);
  EXPECT_EQ(at100["start"], "../ramp/" + ramp_plan.points[1].folder);
  EXPECT_NEAR(std::stod(at10["strain"]), 0.2, 0.02);  // a continued point's strain

  // The ramp 3 -> 5 -> 10 of the same cell: its points are the refinement's.
  const SweepPlan direct = parse_sweep(ramp("[3.0, 5.0, 10.0]"), "direct.toml", ".", {});
  run(direct, dir.path() / "direct");
  for (std::size_t k : {1u, 2u}) {
    auto same = table_row(dir.path() / "direct" / "flowcurves.csv", k);
    auto mine = k == 1 ? at5 : at10;
    for (const char* c : {"gamma_dot", "shear_stress", "frac_bl", "phi_bulk", "steps", "strain"})
      EXPECT_EQ(mine[c], same[c]) << c << " at lambda " << mine["lambda"];
  }

  // A jam's cold start under the matched rule shifts phi by the bulk the
  // ramp gained from its cold start (the refined ramp's first point) to the
  // state the point started from (the extra point below it).
  const SweepPlan matched = parse_sweep(refinement("[10.0, 5.0, 100.0]", refined), "refine.toml",
                                        ".", {"sweep.cold_start_phi=\"matched\""});
  std::vector<PointRecord> records(3);
  for (std::size_t k = 0; k < 3; ++k)
    records[k] = {
        PointStatus::Done,
        "",
        nlohmann::json::parse(test::read_text(out / matched.points[k].folder / "summary.json")),
        {},
        {}};
  const double ramp_first = std::stod(table_row(refined / "flowcurves.csv", 0)["phi_bulk"]);
  const ColdStartChoice cold = choose_cold_start(matched, 0, records, out, false);
  EXPECT_NEAR(cold.config.cell()->phi, 0.58 + (std::stod(at5["phi_bulk"]) - ramp_first), 1e-12);
  EXPECT_NE(std::stod(at5["phi_bulk"]), ramp_first);  // so the shift is not zero

  // The resolved sweep reads back as the same refinement (and resumes).
  const SweepPlan again = load_sweep(out / "sweep.toml", {});
  ASSERT_EQ(again.points.size(), 3u);
  for (std::size_t k = 0; k < 3; ++k) {
    EXPECT_EQ(again.points[k].refines.has_value(), plan.points[k].refines.has_value());
    if (plan.points[k].refines) {
      EXPECT_EQ(again.points[k].refines->ramp, plan.points[k].refines->ramp);
    }
    EXPECT_EQ(again.points[k].continues_from, plan.points[k].continues_from);
    EXPECT_EQ(again.points[k].config.resolved, plan.points[k].config.resolved);
  }
  EXPECT_EQ(run(again, out).skipped, 3u);
}

TEST(RampRefinement, EachPointFindsItsOwnRampAmongSeveral) {
  test::TempDir dir;
  const fs::path refined = dir.path() / "ramp";
  fs::create_directories(refined);
  // Two seeds, lambdas out of order: the ramps are chained by lambda.
  const SweepPlan ramps = parse_sweep(ramp("[30.0, 3.0]"), "ramp.toml", ".", {"cell.seed=[1, 2]"});
  write_file_atomically(refined / "sweep.toml", resolved_sweep_toml(ramps));
  const SweepPlan plan =
      parse_sweep(refinement("[10.0, 50.0]", refined), "refine.toml", ".", {"cell.seed=[2, 1]"});
  ASSERT_EQ(plan.points.size(), 4u);
  for (const auto& p : plan.points) {
    ASSERT_TRUE(p.refines) << p.label;  // one extra point per segment
    const fs::path& from = p.refines->ramp.back();
    const auto q = std::find_if(ramps.points.begin(), ramps.points.end(),
                                [&](const SweepPoint& r) { return refined / r.folder == from; });
    ASSERT_NE(q, ramps.points.end());
    EXPECT_EQ(q->config.cell()->seed, p.config.cell()->seed) << p.label;
    EXPECT_EQ(q->config.fluid.lambda, p.config.fluid.lambda < 30.0 ? 3.0 : 30.0) << p.label;
    const SweepPoint* first = &*q;  // the ramp's cold start
    while (first->continues_from) first = &ramps.points[*first->continues_from];
    EXPECT_EQ(p.refines->ramp.front(), refined / first->folder) << p.label;
  }
}

TEST(RampRefinement, WaitsForTheRampFailsWithItAndSkipsWhatLiesAboveItsJam) {
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
  EXPECT_EQ(table_row(out / "flowcurves.csv", 1)["status"], "pending");

  // The ramp's lambda 30 failed: so does the point that would start from it.
  write_file_atomically(refined / ramp_plan.points[1].folder / "error.txt", "no\n");
  outcome = run(plan, out);
  EXPECT_EQ(outcome.failed, 1u);
  EXPECT_NE(table_row(out / "flowcurves.csv", 1)["error"].find("failed"), std::string::npos);
  fs::remove(refined / ramp_plan.points[1].folder / "error.txt");
  fs::remove(out / plan.points[1].folder / "error.txt");

  // The ramp jammed at lambda 3 and stopped there (its lambda 30 never ran):
  // the point above is skipped, with stop_at_jam or without.
  const fs::path bottom = refined / ramp_plan.points[0].folder / "summary.json";
  auto summary = nlohmann::json::parse(test::read_text(bottom));
  summary["jammed"] = true;
  write_file_atomically(bottom, summary.dump());
  for (const char* stop : {"true", "false"}) {
    const SweepPlan p = parse_sweep(refinement("[100.0]", refined), "r.toml", ".",
                                    {std::string("sweep.stop_at_jam=") + stop});
    const fs::path o = dir.path() / (std::string("stop-") + stop);
    EXPECT_EQ(run(p, o).above_jam, 1u) << stop;
    auto above = table_row(o / "flowcurves.csv", 0);
    EXPECT_EQ(above["status"], "skipped");
    EXPECT_NE(above["error"].find(ramp_plan.points[0].folder), std::string::npos) << above["error"];
  }
  // With the ramp's lambda 30 run from the jammed state (its own stop_at_jam
  // false), a refinement without stop_at_jam starts from it.
  write_file_atomically(top, top_summary);
  const SweepPlan go =
      parse_sweep(refinement("[100.0]", refined), "r.toml", ".", {"sweep.stop_at_jam=false"});
  EXPECT_EQ(run(go, dir.path() / "go").done, 1u);
}

TEST(RampRefinement, APointItCannotPlaceIsRefusedByName) {
  test::TempDir dir;
  const fs::path refined = dir.path() / "ramp";
  planned_ramp(refined);
  // The file's folder is the base of a relative sweep.refines.
  EXPECT_EQ(refusal(refinement("[10.0]", "ramp"), dir.path()), "(accepted)");

  const auto refused = [&](const std::string& text, const std::string& what) {
    const std::string message = refusal(text, ".");
    EXPECT_NE(message.find(what), std::string::npos) << message;
    EXPECT_EQ(message.rfind("refine.toml", 0), 0u) << message;
  };
  refused(refinement("[3.0, 10.0]", refined), "lambda 3 is a point of the refined ramp already");
  refused(refinement("[1.0]", refined), "lambda 1 is below its ramp's first point (lambda 3)");
  refused(
      refinement("[10.0]", refined) + "[friction]\ns_c = 1e-4\n",
      "matches no ramp of " + refined.string() + "; the closest (lambda=3) differs: friction.s_c");
  refused(refinement("[10.0]", dir.path() / "nowhere"),
          "sweep.refines = " + (dir.path() / "nowhere").string() + ": ");
  refused(test::kTinyCell + "[fluid]\nlambda = [10.0]\n[sweep]\nrefines = \"" +
              refined.generic_string() + "\"\n",
          "sweep.refines needs sweep.continuation = true");

  // Only a ramp can be refined, not a grid, nor a refinement.
  const fs::path grid = dir.path() / "grid";
  fs::create_directories(grid);
  write_file_atomically(grid / "sweep.toml",
                        resolved_sweep_toml(parse_sweep(test::kTinyGrid, "g.toml", ".", {})));
  refused(refinement("[10.0]", grid), "not a ramp sweep (no sweep.continuation)");
  const fs::path again = dir.path() / "again";
  fs::create_directories(again);
  write_file_atomically(
      again / "sweep.toml",
      resolved_sweep_toml(parse_sweep(refinement("[10.0]", refined), "r.toml", ".", {})));
  refused(refinement("[20.0]", again), "it refines another sweep itself");
}

TEST(RampRefinement, ItsOutputFolderIsNotTheFolderItRefines) {
  test::TempDir dir;
  const fs::path refined = dir.path() / "ramp";
  const SweepPlan ramp_plan = planned_ramp(refined);
  const SweepPlan plan = parse_sweep(refinement("[10.0]", refined), "r.toml", ".", {});
  SweepRunOptions o;
  o.out = refined / ".";
  try {
    run_sweep(plan, o);
    ADD_FAILURE() << "accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("is the folder this sweep refines"), std::string::npos)
        << e.what();
  }
  EXPECT_EQ(test::read_text(refined / "sweep.toml"), resolved_sweep_toml(ramp_plan));
}

}  // namespace
}  // namespace dilatant::sweep::ramp_refinement_test
