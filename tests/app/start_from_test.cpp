// `dilatant run --start-from`: a cell continues another run's state under a new
// config (as a sweep's continuation does); a file that is not a state of this
// cell is bad input.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "app/cli_runner.hpp"

namespace dilatant::start_from_test {
namespace {

namespace fs = std::filesystem;
using test::read_text;
using test::RunResult;
using TempDir = test::CliDir;

TEST(Cli, StartFromContinuesACheckpointUnderANewConfigAndRefusesOthers) {
  TempDir dir;
  const std::vector<std::string> cell = {
      "--set", "cell.size=[6.0, 5.0, 7.0]", "--set", "run.strain=0.06",
      "--set", "run.transient_strain=0.02", "--set", "run.snapshot_interval=0",
      "-q"};
  const auto with = [&](std::vector<std::string> args) {
    args.insert(args.end(), cell.begin(), cell.end());
    return dir.run(args);
  };
  const fs::path first = dir.path() / "first", second = dir.path() / "second";
  ASSERT_EQ(with({"run", "--out", first.string()}).exit_code, 0);
  const fs::path state = first / "checkpoint.bin";
  const RunResult r = with({"run", "--out", second.string(), "--start-from", state.string(),
                            "--set", "friction.mu0=0.3"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(read_text(second / "config.toml").find("mu0 = 0.3"), std::string::npos);
  EXPECT_TRUE(fs::exists(second / "summary.json"));

  const auto refused = [&](const RunResult& bad, const std::string& part) {
    EXPECT_EQ(bad.exit_code, 2) << bad.err;
    EXPECT_NE(bad.err.find(part), std::string::npos) << bad.err;
    EXPECT_EQ(std::count(bad.err.begin(), bad.err.end(), '\n'), 1) << bad.err;
  };
  const fs::path bad = dir.path() / "bad";
  refused(with({"run", "--out", bad.string(), "--start-from", (first / "config.toml").string()}),
          "not a dilatant checkpoint");
  refused(dir.run({"run", "--out", bad.string(), "--start-from", state.string(), "--set",
                   "cell.size=[8.0, 5.0, 7.0]", "-q"}),
          "not a state of this cell");
  refused(with({"run", "--out", bad.string(), "--start-from", state.string(), "--resume"}),
          "excludes");
  EXPECT_FALSE(fs::exists(bad / "summary.json"));
}

}  // namespace
}  // namespace dilatant::start_from_test
