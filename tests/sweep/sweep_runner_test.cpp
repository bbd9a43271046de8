// Running a sweep: every point in its folder, the table after each, resuming
// an interrupted point from its checkpoint with the same result, a stop before
// anything ran, and continuation along a flow curve (including a chain whose
// first point fails).
#include "sweep/sweep_runner.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <sstream>

#include "analysis/delimited_text.hpp"
#include "app/cli_runner.hpp"
#include "drivers/shear_cell_run.hpp"
#include "sweep/sweep_watch.hpp"
#include "sweep/sweep_work.hpp"
#include "sweep/tiny_sweep.hpp"

namespace dilatant::sweep::sweep_runner_test {
namespace {

namespace fs = std::filesystem;

// The table's rows as fields, with the timing columns blanked (they differ
// between two runs of the same point).
std::vector<std::vector<std::string>> table(const fs::path& file) {
  std::istringstream in(test::read_text(file));
  std::vector<std::vector<std::string>> rows;
  std::vector<std::size_t> timing;
  for (std::string line; std::getline(in, line);) {
    auto fields = analysis::split_fields(line, ',');
    if (rows.empty())
      for (std::size_t k = 0; k < fields.size(); ++k)
        if (fields[k] == "wall_time_s") timing.push_back(k);
    if (!rows.empty())
      for (std::size_t k : timing) fields[k] = "";
    rows.push_back(fields);
  }
  return rows;
}

std::string column(const std::vector<std::vector<std::string>>& rows, std::size_t row,
                   const std::string& name) {
  const auto& h = rows[0];
  return rows[row][static_cast<std::size_t>(std::find(h.begin(), h.end(), name) - h.begin())];
}

SweepRunOptions options(const fs::path& out, const std::atomic<bool>* stop = nullptr) {
  SweepRunOptions o;
  o.out = out;
  o.jobs = 2;
  o.stop = stop;
  return o;
}

TEST(SweepRunner, AnInterruptedPointResumesFromItsCheckpointWithTheSameResult) {
  test::TempDir dir;
  const SweepPlan plan = parse_sweep(test::kTinyGrid, "s.toml", ".", {});
  const SweepOutcome straight = run_sweep(plan, options(dir.path() / "straight"));
  EXPECT_EQ(straight.done, 4u);
  EXPECT_FALSE(straight.interrupted);

  // A stop before anything ran: every point pending, the table written.
  const fs::path out = dir.path() / "pieces";
  const std::atomic<bool> stop{true};
  const SweepOutcome stopped = run_sweep(plan, options(out, &stop));
  EXPECT_TRUE(stopped.interrupted);
  EXPECT_EQ(stopped.pending, 4u);
  const auto pending = table(out / "flowcurves.csv");
  ASSERT_EQ(pending.size(), 5u);
  for (std::size_t r = 1; r < 5; ++r) EXPECT_EQ(column(pending, r, "status"), "pending");
  EXPECT_NE(test::read_text(out / "progress.txt").find("sweep: 0/4 done, 0 running, 0 failed"),
            std::string::npos);

  // Point 2 interrupted after its first step (as SIGINT does), then the sweep
  // again: it resumes point 2 and runs the others.
  const SweepPoint& p = plan.points[2];
  const std::atomic<bool> now{true};
  const CellOutcome first =
      run_shear_cell(p.config, CellRunOptions(RunOptions{out / p.folder, true}, false, &now));
  ASSERT_TRUE(first.interrupted);
  ASSERT_TRUE(fs::exists(out / p.folder / "checkpoint.bin"));
  const SweepOutcome resumed = run_sweep(plan, options(out));
  EXPECT_EQ(resumed.done, 4u);
  EXPECT_EQ(resumed.skipped, 0u);
  EXPECT_EQ(table(out / "flowcurves.csv"), table(dir.path() / "straight" / "flowcurves.csv"));
  const std::string progress = test::read_text(out / "progress.txt");
  EXPECT_NE(progress.find("(this invocation has ended)\nsweep: 4/4 done, 0 running, 0 failed"),
            std::string::npos)
      << progress;
  EXPECT_EQ(progress.find("running:"), std::string::npos) << progress;
  EXPECT_EQ(test::read_text(out / p.folder / "timeseries.csv"),
            test::read_text(dir.path() / "straight" / p.folder / "timeseries.csv"));
}

// DIR/progress.txt while a sweep runs (sweep_watch.hpp): the progress line
// and each running point's share of its run, whether or not a terminal shows
// the line (here none does).
TEST(SweepRunner, ProgressFileNamesTheRunningPointsAndTheirShare) {
  test::TempDir dir;
  const SweepPlan plan = parse_sweep(test::kTinyGrid, "s.toml", ".", {});
  const SweepRunOptions o = options(dir.path());
  SweepWork work(plan, o);
  work.load_folders();
  PointRecord running;
  running.status = PointStatus::Running;
  work.set_record(1, running);
  work.set_fraction(1, 0.4);
  SweepWatch watch(work, o);
  watch.tick(SweepEvents{});
  const std::string text = test::read_text(dir.path() / "progress.txt");
  EXPECT_EQ(text.rfind("# dilatant sweep: progress at 20", 0), 0u) << text;
  EXPECT_NE(text.find("(rewritten every 10 s)\nsweep: 0/4 done, 1 running, 0 failed"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("\nrunning: " + plan.points[1].folder + " 40%\n"), std::string::npos) << text;
}

TEST(SweepRunner, ContinuationStartsEachLambdaFromThePreviousFinalState) {
  test::TempDir dir;
  const std::string text = test::kTinyCell + R"(
[fluid]
lambda = [30.0, 3.0, 10.0]
[sweep]
continuation = true
continuation_strain = 0.2
continuation_transient_strain = 0.05
)";
  const SweepPlan plan = parse_sweep(text, "s.toml", ".", {});
  const fs::path out = dir.path() / "ramp";
  const SweepOutcome outcome = run_sweep(plan, options(out));
  EXPECT_EQ(outcome.done, 3u);
  const auto rows = table(out / "flowcurves.csv");
  EXPECT_EQ(column(rows, 2, "start"), "cold");  // lambda 3
  EXPECT_EQ(column(rows, 3, "start"), plan.points[1].folder);
  EXPECT_EQ(column(rows, 1, "start"), plan.points[2].folder);
  EXPECT_NEAR(std::stod(column(rows, 1, "strain")), 0.2, 0.02);
  EXPECT_NEAR(std::stod(column(rows, 2, "strain")), 0.3, 0.02);
  // A continued point does not rebuild the cell: its first steps are those of
  // the flow its predecessor left, not of the built-in initial profile, so its
  // result differs from a cold start at the same lambda.
  const SweepPlan cold =
      parse_sweep(test::kTinyCell, "c.toml", ".",
                  {"fluid.lambda=10.0", "run.strain=0.2", "run.transient_strain=0.05"});
  run_sweep(cold, options(dir.path() / "cold"));
  const auto cold_rows = table(dir.path() / "cold" / "flowcurves.csv");
  EXPECT_NE(column(rows, 3, "gamma_dot"), column(cold_rows, 1, "gamma_dot"));
  EXPECT_EQ(column(rows, 3, "mobile_spheres"), column(cold_rows, 1, "mobile_spheres"));
}

TEST(SweepRunner, AChainWhoseFirstPointFailsRecordsWhyTheOthersDidNotRun) {
  test::TempDir dir;
  const std::string text = test::kTinyCell + R"(
[fluid]
lambda = [3.0, 30.0]
[sweep]
continuation = true
)";
  const SweepPlan plan = parse_sweep(text, "s.toml", ".", {"cell.phi=0.72"});
  const fs::path out = dir.path() / "impossible";
  const SweepOutcome outcome = run_sweep(plan, options(out));
  EXPECT_EQ(outcome.failed, 2u);
  const auto rows = table(out / "flowcurves.csv");
  EXPECT_NE(column(rows, 1, "error").find("could not pack cell.phi = 0.72"), std::string::npos);
  EXPECT_EQ(column(rows, 2, "error"),
            "not run: it continues from " + plan.points[0].folder + ", which failed");
  EXPECT_EQ(test::read_text(out / plan.points[0].folder / "error.txt"),
            column(rows, 1, "error") + "\n");
}

}  // namespace
}  // namespace dilatant::sweep::sweep_runner_test
