// A folder in use by another dilatant (io/folder_lock.hpp), end to end: while
// this test process holds a folder's lock, `dilatant run` and `dilatant sweep`
// with that --out are refused as bad input (exit 2, one line naming the folder
// and the holder) and write nothing there; once it is released both run.
#include <gtest/gtest.h>

#include <filesystem>
#include <optional>
#include <string>

#include "app/cli_runner.hpp"
#include "io/folder_lock.hpp"
#include "sweep/tiny_sweep.hpp"

namespace dilatant::folder_in_use_test {
namespace {

namespace fs = std::filesystem;

// The one line of a refusal of `folder` held by this test.
void expect_refused(const test::RunResult& r, const fs::path& folder) {
  EXPECT_EQ(r.exit_code, 2) << r.err;
  const std::string start =
      "dilatant: error: " + folder.string() + ": in use by another dilatant (pid ";
  EXPECT_EQ(r.err.substr(0, start.size()), start) << r.err;
  EXPECT_NE(r.err.find(", a test, since "), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << "one line: " << r.err;
}

TEST(FolderInUse, ARunIsRefusedWhileAnotherHoldsItsFolder) {
  test::CliDir dir;
  const fs::path out = dir.path() / "run";
  fs::create_directories(out);
  std::optional<FolderLock> held;
  held.emplace(out, "a test");
  auto args = test::small_cell_run();
  args.insert(args.end(), {"--out", out.string()});
  expect_refused(dir.run(args), out);
  EXPECT_FALSE(fs::exists(out / "config.toml"));
  EXPECT_FALSE(fs::exists(out / "checkpoint.bin"));
  held.reset();
  const test::RunResult again = dir.run(args);
  EXPECT_EQ(again.exit_code, 0) << again.err;
  EXPECT_TRUE(fs::exists(out / "summary.json"));
}

TEST(FolderInUse, ASweepIsRefusedWhileAnotherHoldsItsFolder) {
  test::CliDir dir;
  const fs::path sweep =
      dir.write("sweep.toml", test::kTinyCell + "[friction]\nmu0 = [0.1, 0.4]\n");
  const fs::path out = dir.path() / "sweep";
  fs::create_directories(out);
  std::optional<FolderLock> held;
  held.emplace(out, "a test");
  const std::vector<std::string> args = {"sweep",      sweep.string(), "--out",
                                         out.string(), "--no-plots",   "-q"};
  expect_refused(dir.run(args), out);
  EXPECT_FALSE(fs::exists(out / "points"));
  EXPECT_FALSE(fs::exists(out / "flowcurves.csv"));
  held.reset();
  const test::RunResult again = dir.run(args);
  EXPECT_EQ(again.exit_code, 0) << again.err;
  EXPECT_TRUE(fs::exists(out / "flowcurves.csv"));
}

}  // namespace
}  // namespace dilatant::folder_in_use_test
