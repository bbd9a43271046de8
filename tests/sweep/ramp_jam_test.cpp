// A stress ramp carried to the jam (sweep_plan.hpp, "A ramp that jams"): dry
// enough and dense enough that the literal model flows on its hydrodynamic
// branch at lambda 0.01 and jams once its contacts are boundary-lubricated
// (mu0 1 at nominal phi 0.60, far above phi_max_BL(1) = 0.559: docs/jamming.md).
// The jam is confirmed from a cold start, the ramp stops there, and re-running
// the sweep neither reruns nor loses any of it. (The lambda 0.1 point before the
// jam dilates the bulk from 0.581 to 0.568 and the jam to 0.563; the matched
// cold start at nominal 0.587 jams at 0.545, the nominal one at 0.60 at 0.583:
// a jam's phi_bulk is that of the packing it dilated, docs/sweeps.md.)
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "analysis/delimited_text.hpp"
#include "app/cli_runner.hpp"
#include "drivers/starting_fraction.hpp"
#include "io/input_error.hpp"
#include "sweep/cold_start_choice.hpp"
#include "sweep/sweep_runner.hpp"
#include "sweep/table_row.hpp"

namespace dilatant::sweep::ramp_jam_test {
namespace {

namespace fs = std::filesystem;

constexpr const char* kRamp = R"(
[cell]
size = [8.0, 6.0, 9.0]
phi = 0.60
seed = 3  # flows at lambda 0.01, jams at 1e4 (confirmed cold), with the wall inside the pass
[friction]
law = "stribeck"
mu0 = 1.0
[fluid]
lambda = [0.01, 10000.0, 100000.0]
lubrication = "none"
drag = "none"
[solver]
tolerance = 1e-3  # a jam needs it (docs/model.md "Convergence criterion")
[run]
strain = 0.2
transient_strain = 0.1
snapshot_interval = 0.0
[sweep]
continuation = true
)";

TEST(RampToJam, StopsAtTheFirstJamAndConfirmsItFromAColdStart) {
  test::TempDir dir;
  // Two flowing points before the jam, and the cold start's phi matched to
  // the bulk the jam's stress step met.
  const SweepPlan plan = parse_sweep(
      kRamp, "ramp.toml", ".",
      {"fluid.lambda=[0.01, 0.1, 10000.0, 100000.0]", "sweep.cold_start_phi=\"matched\""});
  SweepRunOptions o;
  o.out = dir.path();
  const SweepOutcome first = run_sweep(plan, o);
  const fs::path table = dir.path() / "flowcurves.csv";
  auto flowing = test::table_row(table, 0), before_jam = test::table_row(table, 1),
       jam = test::table_row(table, 2), above = test::table_row(table, 3);
  ASSERT_EQ(flowing["status"], "done") << flowing["error"];
  ASSERT_EQ(before_jam["status"], "done") << before_jam["error"];
  EXPECT_EQ(flowing["jammed"], "false");
  EXPECT_EQ(before_jam["jammed"], "false");
  EXPECT_EQ(flowing["jam_cold_start"], "");  // flowed: nothing to confirm
  ASSERT_EQ(jam["status"], "done") << jam["error"];
  EXPECT_EQ(jam["jammed"], "true");
  EXPECT_EQ(jam["jam_cold_start"], "jammed");
  EXPECT_TRUE(fs::is_regular_file(dir.path() / jam["dir"] / "cold-start" / "summary.json"));
  // Matched: the nominal phi shifted by the ramp's change of the bulk from its
  // first point to the one the jam continued from (sweep_work.cpp); the cold
  // start's own bulk fraction is reported beside it.
  const double change = std::stod(before_jam["phi_bulk"]) - std::stod(flowing["phi_bulk"]);
  EXPECT_NE(change, 0.0);
  EXPECT_DOUBLE_EQ(std::stod(jam["jam_cold_start_phi"]), 0.60 + change);
  EXPECT_GT(std::stod(jam["jam_cold_start_phi_bulk"]), 0.5);
  EXPECT_EQ(flowing["jam_cold_start_phi"], "");
  EXPECT_EQ(above["status"], "skipped");
  EXPECT_NE(above["error"].find(jam["dir"]), std::string::npos) << above["error"];
  EXPECT_EQ(first.done, 3u);
  EXPECT_EQ(first.above_jam, 1u);

  // Again: everything is on disk, nothing runs, the table is the same.
  const auto before = test::read_text(dir.path() / jam["dir"] / "cold-start" / "summary.json");
  const SweepOutcome again = run_sweep(plan, o);
  EXPECT_EQ(again.skipped, 3u);
  EXPECT_EQ(test::table_row(table, 2)["jam_cold_start"], "jammed");
  EXPECT_EQ(test::table_row(table, 3)["status"], "skipped");
  EXPECT_EQ(test::read_text(dir.path() / jam["dir"] / "cold-start" / "summary.json"), before);
}

TEST(RampToJam, BothRulesCanBeTurnedOffAndAreRefusedWithoutContinuation) {
  const SweepPlan plan =
      parse_sweep(kRamp, "ramp.toml", ".", {"sweep.stop_at_jam=false", "sweep.confirm_jams=false"});
  EXPECT_FALSE(plan.settings.stop_at_jam);
  EXPECT_FALSE(plan.settings.confirm_jams);
  EXPECT_THROW(
      parse_sweep(kRamp, "ramp.toml", ".", {"sweep.continuation=false", "sweep.stop_at_jam=true"}),
      InputError);
}

// Bulk: the cold start's nominal phi is chosen on packings so that it begins
// at the bulk fraction the jammed point began from (the final state of the
// point before it); the choice is kept beside the cold start and read back
// when the sweep runs again. In this gap of 9 R the packings' starting bulk is
// bimodal in phi (0.546-0.557 or 0.589-0.592: the central slab holds two or
// three layers), so the ramp's 0.566 is not reached: the closest packing is
// chosen and the record says so (the search's contract is tested in
// tests/drivers/starting_fraction_test.cpp; in the paper's cell it met its
// targets, docs/sweeps.md "Ramps to the jam").
TEST(RampToJam, TheBulkRuleStartsTheColdStartWhereTheJamBegan) {
  test::TempDir dir;
  // Half the strain of kRamp: the contract below holds whatever the cold start
  // finds (here it flows), and the test costs half (5.8 s instead of 10.5 s in
  // release, 4x that under the sanitizers).
  const SweepPlan plan =
      parse_sweep(kRamp, "ramp.toml", ".",
                  {"sweep.cold_start_phi=\"bulk\"", "run.strain=0.1", "run.transient_strain=0.05"});
  SweepRunOptions o;
  o.out = dir.path();
  run_sweep(plan, o);
  const fs::path table = dir.path() / "flowcurves.csv";
  auto flowing = test::table_row(table, 0), jam = test::table_row(table, 1);
  ASSERT_EQ(jam["status"], "done") << jam["error"];
  ASSERT_EQ(jam["jammed"], "true");
  ASSERT_NE(jam["jam_cold_start"], "pending");
  const double target = checkpoint_bulk_fraction(dir.path() / flowing["dir"] / "checkpoint.bin");
  EXPECT_DOUBLE_EQ(std::stod(jam["jam_phi_bulk_start"]), target);
  const double start = std::stod(jam["jam_cold_start_phi_bulk_start"]);
  // The cold start ran at the chosen phi, and its packing begins where the
  // choice says (the same seed builds the same packing).
  const double phi = std::stod(jam["jam_cold_start_phi"]);
  Config cold = plan.points[1].config;
  cold.cell()->phi = phi;
  EXPECT_DOUBLE_EQ(starting_bulk_fraction(cold), start);
  const fs::path choice = dir.path() / jam["dir"] / "cold-start" / kPhiChoiceFile;
  const auto record = nlohmann::json::parse(test::read_text(choice));
  EXPECT_EQ(record["rule"], "bulk");
  EXPECT_EQ(record["within_tolerance"].get<bool>(), std::abs(start - target) <= kBulkTolerance);
  ASSERT_GE(record["tried"].size(), 1u);
  for (const auto& t : record["tried"])  // the closest packing tried
    EXPECT_LE(std::abs(start - target), std::abs(t["phi_bulk"].get<double>() - target));
  EXPECT_EQ(flowing["jam_phi_bulk_start"], "");  // flowed: no cold start

  // Run again: the recorded choice is read back, not made again (a marked
  // target shows in the table), and the cold start is not rerun.
  auto marked = record;
  marked["target_phi_bulk"] = 0.123456;
  std::ofstream(choice) << marked.dump(2);
  const auto cold_summary = dir.path() / jam["dir"] / "cold-start" / "summary.json";
  const auto written = fs::last_write_time(cold_summary);
  run_sweep(plan, o);
  EXPECT_EQ(test::table_row(table, 1)["jam_phi_bulk_start"], "0.123456");
  EXPECT_EQ(test::table_row(table, 1)["jam_cold_start"], jam["jam_cold_start"]);
  EXPECT_EQ(fs::last_write_time(cold_summary), written);
}

TEST(RampToJam, TheColdStartsPhiIsNominalMatchedOrBulkAndNothingElse) {
  EXPECT_EQ(parse_sweep(kRamp, "ramp.toml", ".", {}).settings.cold_start_phi,
            SweepSettings::ColdStartPhi::Nominal);
  EXPECT_EQ(parse_sweep(kRamp, "ramp.toml", ".", {"sweep.cold_start_phi=\"matched\""})
                .settings.cold_start_phi,
            SweepSettings::ColdStartPhi::Matched);
  try {
    parse_sweep(kRamp, "ramp.toml", ".", {"sweep.cold_start_phi=\"loose\""});
    FAIL() << "a cold_start_phi of \"loose\" was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("sweep.cold_start_phi"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("\"nominal\", \"matched\" or \"bulk\""), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace dilatant::sweep::ramp_jam_test
