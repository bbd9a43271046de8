// A run whose result is not valid says why (issue: `valid: false` ended with
// exit 0 and "results in out/..." and no reason): summary.json lists the
// reasons (invalid_reasons, empty exactly when valid) and the CLI repeats them
// in one warning line; the exit code stays 0, as the run did what it was
// asked (docs/shear-cell.md "Validity").
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>

#include "app/cli_runner.hpp"

namespace dilatant::test::invalid_run_test {
namespace {

namespace fs = std::filesystem;

RunResult run_cell(const CliDir& dir, const fs::path& out, const std::string& s_lim) {
  return dir.run({"run", "--out", out.string(), "--set", "cell.size=[6.0, 5.0, 7.0]", "--set",
                  "run.strain=0.05", "--set", "run.transient_strain=0.01", "--set",
                  "run.snapshot_interval=0", "--set", "friction.s_lim=" + s_lim});
}

TEST(InvalidRun, SaysWhyInTheSummaryAndInOneWarningLine) {
  CliDir dir;
  // s_lim 1e-3: about half the contacts lie beyond it.
  const RunResult bad = run_cell(dir, dir.path() / "bad", "1e-3");
  ASSERT_EQ(bad.exit_code, 0) << bad.err;
  const auto summary = nlohmann::json::parse(read_text(dir.path() / "bad" / "summary.json"));
  EXPECT_FALSE(summary["valid"].get<bool>());
  ASSERT_FALSE(summary["invalid_reasons"].empty());
  const std::string first = summary["invalid_reasons"][0].get<std::string>();
  EXPECT_NE(first.find("beyond friction.s_lim"), std::string::npos) << first;
  const auto warning = bad.err.find("warning: the result is not valid: " + first);
  EXPECT_NE(warning, std::string::npos) << bad.err;
  EXPECT_EQ(bad.err.find('\n', warning), bad.err.rfind('\n')) << bad.err;  // one line, the last
  EXPECT_NE(bad.out.find("(not valid: see the warning)"), std::string::npos) << bad.out;

  // The default s_lim, over long enough a strain for a linear profile.
  const RunResult good = dir.run({"run", "--out", (dir.path() / "good").string(), "--set",
                                  "cell.size=[8.0, 5.0, 9.0]", "--set", "run.strain=0.5", "--set",
                                  "run.transient_strain=0.1", "--set", "run.snapshot_interval=0"});
  ASSERT_EQ(good.exit_code, 0) << good.err;
  const auto fine = nlohmann::json::parse(read_text(dir.path() / "good" / "summary.json"));
  EXPECT_TRUE(fine["valid"].get<bool>());
  EXPECT_TRUE(fine["invalid_reasons"].empty());
  EXPECT_EQ(good.err.find("not valid"), std::string::npos) << good.err;
}

}  // namespace
}  // namespace dilatant::test::invalid_run_test
