// A read-only output folder (issue 19, item 2): the run stops with exit 2 and
// one line naming the path and the reason, and the next run, with the folder
// writable again, completes. Permission bits do not stop root, so as root the
// run is started as `nobody` (setpriv, util-linux) from a copy of the
// executable in the test's own folder (the build folder may be private).
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>

#include "app/cli_runner.hpp"

namespace dilatant::read_only_test {
namespace {

namespace fs = std::filesystem;

const std::vector<std::string> kSmallRun = test::small_cell_run();

// r-x for everyone: the folder can be entered and listed, not written.
constexpr fs::perms kReadOnly = fs::perms::owner_read | fs::perms::owner_exec |
                                fs::perms::group_read | fs::perms::group_exec |
                                fs::perms::others_read | fs::perms::others_exec;

class ReadOnlyOutput : public ::testing::Test {
 protected:
  void SetUp() override {
    executable_ = dir_.path() / "dilatant";
    fs::copy_file(DILATANT_EXECUTABLE, executable_);
    fs::permissions(dir_.path(), fs::perms::all);  // others reach the folder
    if (::geteuid() == 0) {
      launcher_ = "setpriv --reuid=65534 --regid=65534 --clear-groups --";
      const auto probe = dir_.run({"--version"}, "", launcher_, executable_.string());
      if (probe.exit_code != 0)
        GTEST_SKIP() << "running as root and cannot drop to uid 65534: " << probe.err;
    }
  }
  test::RunResult run(const fs::path& out) const {
    auto args = kSmallRun;
    args.insert(args.end(), {"--out", out.string()});
    return dir_.run(args, "", launcher_, executable_.string());
  }
  static void expect_one_line_naming(const test::RunResult& r, const std::string& what) {
    EXPECT_EQ(r.exit_code, 2) << r.err;  // bad input (issue 31, item 7)
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_NE(r.err.find(what), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("Permission denied"), std::string::npos) << r.err;
  }

  test::CliDir dir_;
  fs::path executable_;
  std::string launcher_;
};

// The output folder cannot be created: its parent is read-only.
TEST_F(ReadOnlyOutput, AFolderThatCannotBeCreatedIsNamedAndTheNextRunCompletes) {
  const fs::path parent = dir_.path() / "read-only";
  fs::create_directory(parent);
  fs::permissions(parent, kReadOnly);
  const fs::path out = parent / "out";
  expect_one_line_naming(run(out), out.string());
  EXPECT_FALSE(fs::exists(out));

  fs::permissions(parent, fs::perms::all);
  const auto again = run(out);
  EXPECT_EQ(again.exit_code, 0) << again.err;
  EXPECT_TRUE(fs::exists(out / "summary.json"));
}

// The output folder exists and is read-only: nothing can be written in it.
TEST_F(ReadOnlyOutput, AReadOnlyFolderIsNamedNothingIsLeftAndTheNextRunCompletes) {
  const fs::path out = dir_.path() / "out";
  fs::create_directory(out);
  fs::permissions(out, kReadOnly);
  expect_one_line_naming(run(out), out.string());
  EXPECT_TRUE(fs::is_empty(out));

  fs::permissions(out, fs::perms::all);
  const auto again = run(out);
  EXPECT_EQ(again.exit_code, 0) << again.err;
  EXPECT_TRUE(fs::exists(out / "summary.json"));
}

}  // namespace
}  // namespace dilatant::read_only_test
