// A sweep point that is not steady runs on, one fresh averaging window at a
// time, up to sweep.extend_unsteady_to (sweep/unsteady_extension.hpp): the
// extended configurations, how a folder is recognised, when a point runs on,
// and a tiny ramp whose points start out unsteady (their wall still speeds up
// at strain 0.3: drift +7% to +11% +- 2-3%, measured).
#include "sweep/unsteady_extension.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>

#include "app/cli_runner.hpp"
#include "drivers/shear_cell_run.hpp"
#include "io/io_test_files.hpp"
#include "sweep/point_folder.hpp"
#include "sweep/sweep_runner.hpp"
#include "sweep/tiny_sweep.hpp"

namespace dilatant::sweep::unsteady_extension_test {
namespace {

namespace fs = std::filesystem;

// kTinyCell (strain 0.3, transient 0.1: a window of 0.2) as a ramp of two
// lambdas, with rows every 0.004 so that each window's halves hold enough
// rows for the steadiness test's block errors.
std::string tiny_ramp(const std::string& settings) {
  return "[sweep]\ncontinuation = true\n" + settings + "\n" + test::kTinyCell +
         "output_interval = 0.004\n\n[fluid]\nlambda = [3.0, 30.0]\n";
}

nlohmann::json summary_of(const fs::path& folder) {
  return nlohmann::json::parse(test::read_text(folder / "summary.json"));
}

SweepRunOptions options(const fs::path& out) {
  SweepRunOptions o;
  o.out = out;
  o.jobs = 1;
  return o;
}

TEST(UnsteadyExtension, EachExtensionIsOneMoreWindowPastEverythingBefore) {
  const SweepPlan plan = parse_sweep(tiny_ramp(""), "s.toml", ".", {});
  const Config& planned = plan.points[0].config;  // strain 0.3, transient 0.1
  EXPECT_EQ(resolved_toml(extended_config(planned, 0)), resolved_toml(planned));
  const Config third = extended_config(planned, 3);
  EXPECT_EQ(third.run.strain, 0.9);  // 0.3 + 3 x 0.2, to 12 digits
  EXPECT_EQ(third.run.transient_strain, 0.7);
  EXPECT_EQ(resolved_toml(third), resolved_toml(Config(third)));
  EXPECT_NE(resolved_toml(third).find("strain = 0.9\n"), std::string::npos);
  // Recognised from its text, up to the cap; anything else is extension 0.
  EXPECT_EQ(extensions_in(resolved_toml(third), planned, 1.5), 3);
  EXPECT_EQ(extensions_in(resolved_toml(third), planned, 0.8), 0);  // beyond the cap
  EXPECT_EQ(extensions_in(resolved_toml(planned), planned, 1.5), 0);
  Config half = planned;  // strain 0.4: half a window on
  half.run.strain = 0.4;
  half.run.transient_strain = 0.2;
  EXPECT_EQ(extensions_in(resolved_toml(half), planned, 1.5), 0);
  Config moved = third;  // the strain of extension 3 with another transient
  moved.run.transient_strain = 0.5;
  EXPECT_EQ(extensions_in(resolved_toml(moved), planned, 1.5), 0);
  EXPECT_EQ(extensions_in("not toml [", planned, 1.5), 0);
}

TEST(UnsteadyExtension, OnlyAPointTestedAndNotSteadyRunsOnWhileAWindowFitsUnderTheCap) {
  const SweepPlan plan = parse_sweep(tiny_ramp(""), "s.toml", ".", {});
  const Config& c = plan.points[0].config;  // strain 0.3: the next window ends at 0.5
  const nlohmann::json drifting = {{"steady", false}, {"jammed", false}};
  EXPECT_TRUE(needs_extension(drifting, c, 0.5));
  EXPECT_FALSE(needs_extension(drifting, c, 0.49));  // one more window passes the cap
  EXPECT_FALSE(needs_extension({{"steady", true}, {"jammed", false}}, c, 9.0));
  EXPECT_FALSE(needs_extension({{"steady", nullptr}, {"jammed", false}}, c, 9.0));  // untested
  EXPECT_FALSE(needs_extension({{"steady", nullptr}, {"jammed", true}}, c, 9.0));
  EXPECT_FALSE(needs_extension(nlohmann::json::object(), c, 9.0));
}

TEST(UnsteadyExtension, AFolderOfAnExtendedRunIsThePointsWithItsCount) {
  test::TempDir dir;
  const SweepPlan plan = parse_sweep(tiny_ramp("extend_unsteady_to = 1.5"), "s.toml", ".", {});
  const SweepPoint& p = plan.points[0];
  const fs::path folder = dir.path() / p.folder;
  dir.write(p.folder + "/config.toml", resolved_toml(extended_config(p.config, 2)));
  dir.write(p.folder + "/checkpoint.bin", "x");  // stopped during its second extension
  PointFolder f = inspect_point_folder(p, folder, 1.5);
  EXPECT_EQ(f.state, PointState::Resumable);
  EXPECT_EQ(f.extensions, 2);
  dir.write(p.folder + "/summary.json", "{}");
  EXPECT_EQ(inspect_point_folder(p, folder, 1.5).state, PointState::Done);
  // Without the setting, or with a cap below it, it is refused, saying why.
  EXPECT_NE(test::input_error_message([&] { inspect_point_folder(p, folder, std::nullopt); })
                .find(folder.string() +
                      ": holds this point run on to strain 0.7 because it was not steady "
                      "(sweep.extend_unsteady_to), which this sweep does not set: set "
                      "sweep.extend_unsteady_to to at least 0.7"),
            std::string::npos);
  EXPECT_NE(test::input_error_message([&] {
              inspect_point_folder(p, folder, 0.6);
            }).find("which this sweep caps at 0.6"),
            std::string::npos);
  // A strain that is no whole number of windows on is another configuration.
  dir.write(p.folder + "/config.toml",
            resolved_toml(
                parse_sweep(tiny_ramp(""), "s.toml", ".", {"run.strain=0.4"}).points[0].config));
  EXPECT_NE(test::input_error_message([&] {
              inspect_point_folder(p, folder, 1.5);
            }).find("run.strain = 0.4 there, 0.3 in this sweep"),
            std::string::npos);
}

TEST(UnsteadyExtension, ACapBelowAPointsStrainIsRefused) {
  const std::string message = test::input_error_message(
      [&] { parse_sweep(tiny_ramp("extend_unsteady_to = 0.2"), "s.toml", ".", {}); });
  EXPECT_NE(message.find("s.toml: sweep.extend_unsteady_to = 0.2 is below the run.strain of "
                         "point points/000-lambda=3 (0.3)"),
            std::string::npos)
      << message;
  const std::string text = test::input_error_message(
      [&] { parse_sweep(tiny_ramp("extend_unsteady_to = \"long\""), "s.toml", ".", {}); });
  EXPECT_NE(text.find("sweep.extend_unsteady_to = long: expected a number"), std::string::npos)
      << text;
  // The resolved sweep keeps it, and reads back as the same sweep.
  const SweepPlan plan = parse_sweep(tiny_ramp("extend_unsteady_to = 1.5"), "s.toml", ".", {});
  const SweepPlan again = parse_sweep(resolved_sweep_toml(plan), "s.toml", ".", {});
  EXPECT_EQ(again.settings.extend_unsteady_to, 1.5);
  EXPECT_EQ(resolved_sweep_toml(again), resolved_sweep_toml(plan));
}

// The tiny ramp's points are not steady at their planned strain; with the
// setting each runs on until its last window is steady or the next would pass
// the cap, every window before that one having failed the test. The extended
// cold point's result is that of a run made with its final configuration from
// the start (the same rows, so the same viscosity), and the ramp's second
// point starts from the extended final state.
TEST(UnsteadyExtension, ATinyRampRunsOnUntilSteadyOrTheCap) {
  test::TempDir dir;
  const SweepPlan plain = parse_sweep(tiny_ramp(""), "s.toml", ".", {});
  ASSERT_EQ(run_sweep(plain, options(dir.path() / "plain")).done, 2u);
  for (const SweepPoint& p : plain.points)
    ASSERT_EQ(summary_of(dir.path() / "plain" / p.folder)["steady"], false) << p.folder;

  const double cap = 1.5;
  const SweepPlan plan = parse_sweep(tiny_ramp("extend_unsteady_to = 1.5"), "s.toml", ".", {});
  const fs::path out = dir.path() / "extended";
  ASSERT_EQ(run_sweep(plan, options(out)).done, 2u);
  for (const SweepPoint& p : plan.points) {
    const PointFolder f = inspect_point_folder(p, out / p.folder, cap);
    ASSERT_EQ(f.state, PointState::Done);
    EXPECT_GE(f.extensions, 1) << p.folder;
    const Config last = extended_config(p.config, f.extensions);
    const nlohmann::json s = summary_of(out / p.folder);
    EXPECT_NEAR(s["strain"].get<double>(), last.run.strain, 0.01) << p.folder;
    EXPECT_TRUE(s["steady"] == true || !needs_extension(s, last, cap)) << p.folder;
    EXPECT_EQ(s["steady"], true) << p.folder;  // measured: steady by strain 0.9
  }
  // The cold point: rows and viscosity of its final configuration run whole.
  const SweepPoint& first = plan.points[0];
  const int k = inspect_point_folder(first, out / first.folder, cap).extensions;
  const fs::path whole = dir.path() / "whole";
  run_shear_cell(extended_config(first.config, k), CellRunOptions{RunOptions{whole, true}});
  EXPECT_EQ(test::read_text(whole / "timeseries.csv"),
            test::read_text(out / first.folder / "timeseries.csv"));
  EXPECT_EQ(summary_of(whole)["eta"], summary_of(out / first.folder)["eta"]);
  // The second point from that final state: as a run continued from it.
  const SweepPoint& second = plan.points[1];
  const int k2 = inspect_point_folder(second, out / second.folder, cap).extensions;
  const fs::path next = dir.path() / "next";
  CellRunOptions o{RunOptions{next, true}};
  o.start_from = whole / "checkpoint.bin";
  run_shear_cell(extended_config(second.config, k2), o);
  EXPECT_EQ(summary_of(next)["eta"], summary_of(out / second.folder)["eta"]);
}

// Turned on for a sweep that already ran: a point a later point continues
// from keeps its run (its final state is that point's start); the ramp's last
// point runs on. A second invocation changes nothing.
TEST(UnsteadyExtension, APointAnotherContinuesFromIsNotExtendedAfterwards) {
  test::TempDir dir;
  const fs::path out = dir.path() / "sweep";
  const SweepPlan plain = parse_sweep(tiny_ramp(""), "s.toml", ".", {});
  ASSERT_EQ(run_sweep(plain, options(out)).done, 2u);
  const SweepPlan plan = parse_sweep(tiny_ramp("extend_unsteady_to = 1.5"), "s.toml", ".", {});
  const SweepOutcome later = run_sweep(plan, options(out));
  EXPECT_EQ(later.done, 2u);
  EXPECT_EQ(inspect_point_folder(plan.points[0], out / plan.points[0].folder, 1.5).extensions, 0);
  EXPECT_GE(inspect_point_folder(plan.points[1], out / plan.points[1].folder, 1.5).extensions, 1);
  const std::string series = test::read_text(out / plan.points[1].folder / "timeseries.csv");
  EXPECT_EQ(run_sweep(plan, options(out)).skipped, 2u);
  EXPECT_EQ(test::read_text(out / plan.points[1].folder / "timeseries.csv"), series);
}

}  // namespace
}  // namespace dilatant::sweep::unsteady_extension_test
