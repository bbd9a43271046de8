// `dilatant run --dump-steps`: step problems on disk (drivers/step_dumps.hpp)
// change no result, and options that choose no step, a negative count or a
// scene are bad input (exit 2, one line naming the option).
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "app/cli_runner.hpp"

namespace dilatant::app::dump_steps_cli_test {
namespace {

namespace fs = std::filesystem;
using test::read_text;
using test::RunResult;
using TempDir = test::CliDir;

const std::vector<std::string> kCell = {
    "--set", "cell.size=[6.0, 5.0, 7.0]", "--set", "run.strain=0.04",
    "--set", "run.transient_strain=0.01", "--set", "run.snapshot_interval=0",
    "-q"};

RunResult run_cell(TempDir& dir, std::vector<std::string> args) {
  args.insert(args.begin(), "run");
  args.insert(args.end(), kCell.begin(), kCell.end());
  return dir.run(args);
}

// The dumps are written beside a run whose results are those of the same
// run without them, byte for byte (the time series, contacts, checkpoint).
TEST(Cli, DumpStepsWritesChosenStepsAndChangesNoResult) {
  TempDir dir;
  const fs::path plain = dir.path() / "plain", dumped = dir.path() / "dumped";
  const fs::path dumps = dir.path() / "dumps";
  ASSERT_EQ(run_cell(dir, {"--out", plain.string()}).exit_code, 0);
  const RunResult r = run_cell(dir, {"--out", dumped.string(), "--dump-steps", dumps.string(),
                                     "--dump-every", "5", "--dump-max", "2"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const char* f : {"timeseries.csv", "contacts.csv", "checkpoint.bin", "velocity_profile.csv"})
    EXPECT_EQ(read_text(plain / f), read_text(dumped / f)) << f;
  EXPECT_TRUE(fs::exists(dumps / "step-0000001.bin"));
  EXPECT_TRUE(fs::exists(dumps / "step-0000006.bin"));
  EXPECT_TRUE(fs::exists(dumps / "config.toml"));
  const std::string index = read_text(dumps / "index.csv");
  EXPECT_EQ(std::count(index.begin(), index.end(), '\n'), 3) << index;  // header + 2
}

void expect_refused(const RunResult& r, const std::string& culprit) {
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_NE(r.err.find(culprit), std::string::npos) << r.err;
}

TEST(Cli, DumpStepsThatChooseNoStepOrNegativeCountsAreRefused) {
  TempDir dir;
  const std::string dumps = (dir.path() / "dumps").string();
  const std::string out = (dir.path() / "out").string();
  expect_refused(run_cell(dir, {"--out", out, "--dump-steps", dumps}), "--dump-every");
  expect_refused(run_cell(dir, {"--out", out, "--dump-steps", dumps, "--dump-every", "-1"}),
                 "'-1' is not a number >= 0");
  expect_refused(run_cell(dir, {"--out", out, "--dump-every", "3"}), "--dump-steps");
  EXPECT_FALSE(fs::exists(dir.path() / "out" / "summary.json"));
}

}  // namespace
}  // namespace dilatant::app::dump_steps_cli_test
