// A disk that fills up (issue 19, item 2), simulated with the shell's file
// size limit (ulimit -f, RLIMIT_FSIZE; SIGXFSZ ignored so that the write
// fails with EFBIG the way a full disk fails it with ENOSPC): the run stops
// with exit 1 and one line naming the file and the reason, leaves no .part
// file and no summary.json, and the next run with space completes.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

#include "app/cli_runner.hpp"

namespace dilatant::full_disk_test {
namespace {

namespace fs = std::filesystem;

TEST(FullDisk, AFailedWriteStopsTheRunCleanlyAndTheNextRunCompletes) {
  test::CliDir dir;
  const fs::path out = dir.path() / "out";
  const std::vector<std::string> args = {"run",
                                         "--set",
                                         "cell.size=[6.0, 5.0, 7.0]",
                                         "--set",
                                         "run.transient_strain=0.01",
                                         "--set",
                                         "run.strain=0.05",
                                         "--set",
                                         "run.checkpoint_interval=0.01",
                                         "--set",
                                         "run.snapshot_interval=0",
                                         "--out",
                                         out.string(),
                                         "-q"};
  // Files up to 4 KiB: config.toml fits, the first checkpoint (~7 KiB) does not.
  const auto full = dir.run(args, "trap '' XFSZ; ulimit -f 8;");
  EXPECT_EQ(full.exit_code, 1) << full.err;
  EXPECT_EQ(std::count(full.err.begin(), full.err.end(), '\n'), 1) << full.err;
  EXPECT_NE(full.err.find("checkpoint.bin"), std::string::npos) << full.err;
  EXPECT_NE(full.err.find("File too large"), std::string::npos) << full.err;
  EXPECT_FALSE(fs::exists(out / "summary.json"));
  for (const auto& e : fs::directory_iterator(out))
    EXPECT_NE(e.path().extension(), ".part") << e.path();

  const auto again = dir.run(args);
  EXPECT_EQ(again.exit_code, 0) << again.err;
  EXPECT_TRUE(fs::exists(out / "summary.json"));
}

}  // namespace
}  // namespace dilatant::full_disk_test
