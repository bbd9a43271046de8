// "Did you mean": a mistyped command, section or key is answered with the one
// most likely meant (io/text.hpp closest_word(): edit distance with adjacent
// swaps, within a third of the word). Before, a misspelt command said "A
// subcommand is required" and a key typo listed every key of its section.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <fstream>
#include <string>
#include <string_view>

#include "app/cli_runner.hpp"
#include "io/config.hpp"
#include "io/input_error.hpp"
#include "io/text.hpp"

namespace dilatant::did_you_mean_test {
namespace {

using ::testing::HasSubstr;

constexpr std::array<std::string_view, 6> kCommands = {"run",  "sweep", "analyze",
                                                       "plot", "jam",   "predict"};

TEST(DidYouMean, FindsTheWordATypoMeant) {
  EXPECT_EQ(closest_word("rnu", kCommands), "run");          // a swap
  EXPECT_EQ(closest_word("swep", kCommands), "sweep");       // a deletion
  EXPECT_EQ(closest_word("analyse", kCommands), "analyze");  // a substitution
  EXPECT_EQ(closest_word("jamm", kCommands), "jam");         // an insertion
  EXPECT_EQ(closest_word("simulate", kCommands), "");        // nothing close
  EXPECT_EQ(closest_word("", kCommands), "");
  EXPECT_EQ(did_you_mean("predcit", kCommands), " (did you mean 'predict'?)");
  EXPECT_EQ(did_you_mean("xyz", kCommands), "");
}

std::string message(const std::string& text, const std::vector<std::string>& overrides = {}) {
  try {
    (void)parse_config(text, "test.toml", "/base", overrides);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(DidYouMean, ConfigTyposNameTheKeyMeant) {
  EXPECT_THAT(message("[cell]\nsizes = [8.0, 5.0, 9.0]\n"), HasSubstr("(did you mean 'size'?)"));
  EXPECT_THAT(message("[cel]\nphi = 0.5\n"), HasSubstr("unknown section (did you mean 'cell'?)"));
  EXPECT_THAT(message("[cell]\n", {"frcition.mu0=0.3"}), HasSubstr("(did you mean 'friction'?)"));
  EXPECT_THAT(message("[cell]\n", {"friction.mu=0.3"}), HasSubstr("(did you mean 'mu0'?)"));
}

TEST(DidYouMean, ASweepSettingTypoNamesTheSettingMeant) {
  test::CliDir dir;
  std::ofstream(dir.path() / "s.toml")
      << "[cell]\nsize = [6.0, 5.0, 7.0]\n[sweep]\njobz = 2\n[fluid]\nlambda = [1.0, 2.0]\n";
  const test::RunResult r =
      dir.run({"sweep", (dir.path() / "s.toml").string(), "--out", (dir.path() / "o").string()});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_THAT(r.err, HasSubstr("sweep.jobz: unknown key (did you mean 'jobs'?)"));
}

TEST(DidYouMean, AMistypedCommandIsNamedInOneLine) {
  test::CliDir dir;
  const test::RunResult r = dir.run({"rnu", "--set", "cell.phi=0.5"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_THAT(r.err, HasSubstr("'rnu' is not a command (did you mean 'run'?)"));
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
}

}  // namespace
}  // namespace dilatant::did_you_mean_test
