// A mistyped size must not hang the set-up (issue: cell.size = [2000, 2000,
// 2000] spun for over 12 minutes, silent, ignoring SIGINT): a cell or
// sediment estimated to hold more than its max_spheres is refused when the
// config is read, naming the key and the estimate (exit 2 from the CLI), and
// runs once the user raises the limit.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "app/cli_runner.hpp"
#include "io/config.hpp"
#include "io/input_error.hpp"

namespace dilatant::config_size_limit_test {
namespace {

using ::testing::HasSubstr;

std::string message(const std::string& text, const std::vector<std::string>& overrides) {
  try {
    (void)parse_config(text, "test.toml", "/base", overrides);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(ConfigSizeLimit, AHugeCellIsRefusedWithItsEstimate) {
  // 2000^3 at phi 0.58, radii in [0.8, 1] (<r^3> = 0.738): 1.5e9 particles.
  const std::string m = message("[cell]\nsize = [2000.0, 2000.0, 2000.0]\n", {});
  EXPECT_THAT(m, HasSubstr("test.toml"));
  EXPECT_THAT(m, HasSubstr("cell.size"));
  EXPECT_THAT(m, HasSubstr("holds about 1.5e+09 spheres"));
  EXPECT_THAT(m, HasSubstr("cell.max_spheres = 1000000"));
  EXPECT_THAT(message("[cell]\n", {"cell.size=[1e30, 8.0, 10.0]"}), HasSubstr("cell.size"));
  // The paper's cell is far below; raising the limit lets a large cell through.
  EXPECT_EQ(message("[cell]\n", {}), "");
  EXPECT_EQ(message("[cell]\nsize = [200.0, 200.0, 200.0]\nmax_spheres = 3000000\n", {}), "");
  EXPECT_THAT(message("[sediment]\nsize = [500.0, 500.0, 500.0]\n", {}),
              HasSubstr("sediment.max_spheres"));
}

TEST(ConfigSizeLimit, TheCliRefusesAHugeCellAtOnceWithExitTwo) {
  test::CliDir dir;
  const test::RunResult r = dir.run({"run", "--set", "cell.size=[2000.0, 2000.0, 2000.0]", "--out",
                                     (dir.path() / "out").string()});
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_THAT(r.err, HasSubstr("cell.size"));
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
}

}  // namespace
}  // namespace dilatant::config_size_limit_test
