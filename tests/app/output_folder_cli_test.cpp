// The output folder of `dilatant run` (issue 31, item 7): a fresh run into a
// folder an earlier run used removes the files a run owns (its snapshots/ and
// cell.pvd once stayed beside the new results) and keeps the user's own; a
// folder that is a file is exit 2 with one line naming it.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>

#include "app/cli_runner.hpp"

namespace dilatant::app::output_folder_cli_test {
namespace {

namespace fs = std::filesystem;

std::vector<std::string> small_run(const fs::path& out, const std::string& snapshot_interval) {
  auto args = test::small_cell_run();
  args.insert(args.end(),
              {"--set", "run.snapshot_interval=" + snapshot_interval, "--out", out.string()});
  return args;
}

TEST(OutputFolderCli, AFreshRunRemovesAnEarlierRunsFilesAndKeepsTheUsers) {
  test::CliDir dir;
  const fs::path out = dir.path() / "out";
  ASSERT_EQ(dir.run(small_run(out, "0.01")).exit_code, 0);
  ASSERT_TRUE(fs::exists(out / "cell.pvd"));
  ASSERT_TRUE(fs::exists(out / "snapshots"));
  std::ofstream(out / "notes.txt") << "mine\n";
  std::ofstream(out / "snapshots" / "drawing.png") << "mine\n";

  const auto again = dir.run(small_run(out, "0"));
  ASSERT_EQ(again.exit_code, 0) << again.err;
  EXPECT_FALSE(fs::exists(out / "cell.pvd"));
  EXPECT_FALSE(fs::exists(out / "snapshots" / "particles_0000.vtp"));
  EXPECT_TRUE(fs::exists(out / "snapshots" / "drawing.png")) << "not the run's file";
  EXPECT_TRUE(fs::exists(out / "notes.txt"));
  EXPECT_TRUE(fs::exists(out / "summary.json"));
}

TEST(OutputFolderCli, AFileInPlaceOfTheFolderIsExitTwoNamingIt) {
  test::CliDir dir;
  const fs::path file = dir.path() / "out";
  std::ofstream(file) << "a file\n";
  for (const fs::path& out : {file, file / "sub"}) {
    const auto r = dir.run(small_run(out, "0"));
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_NE(r.err.find(out.string() + ": cannot"), std::string::npos) << r.err;
  }
}

}  // namespace
}  // namespace dilatant::app::output_folder_cli_test
