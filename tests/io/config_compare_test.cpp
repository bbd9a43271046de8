// Whether a run folder's config.toml is the run of a configuration
// (io/config_compare.hpp): the test a resume and a sweep's point pass before
// continuing a state. A run written by an older version lacks the keys added
// since; at their defaults they are the same run, set otherwise they are not.
#include "io/config_compare.hpp"

#include <gtest/gtest.h>

#include <string>

#include "io/config.hpp"

namespace dilatant::config_compare_test {
namespace {

// The resolved text without the line of one key: what a version before that
// key wrote.
std::string without_line(std::string text, const std::string& key_line_start) {
  const auto at = text.find("\n" + key_line_start);
  EXPECT_NE(at, std::string::npos) << key_line_start;
  const auto end = text.find('\n', at + 1);
  return text.erase(at, end - at);
}

TEST(ConfigCompare, TheSameConfigurationIsTheSameRun) {
  const Config c = default_cell_config({"cell.phi=0.58"});
  EXPECT_EQ(config_difference(resolved_toml(c), c), std::nullopt);
  const Config other = default_cell_config({"cell.phi=0.59"});
  const auto d = config_difference(resolved_toml(c), other, "in this sweep");
  ASSERT_TRUE(d);
  EXPECT_EQ(*d, "cell.phi = 0.58 there, 0.59 in this sweep");
}

TEST(ConfigCompare, AKeyAnOlderVersionDidNotWriteIsTheSameRunAtItsDefault) {
  const Config c = default_cell_config({});
  const std::string older = without_line(resolved_toml(c), "normal_stress =");
  EXPECT_EQ(config_difference(older, c), std::nullopt);
  // Set away from its default, the run without it is another run.
  const Config set = default_cell_config({"cell.wall_friction=0.7"});
  const auto d = config_difference(without_line(resolved_toml(set), "wall_friction ="), set);
  ASSERT_TRUE(d);
  EXPECT_EQ(*d, "cell.wall_friction = (absent) there, 0.7 here");
}

TEST(ConfigCompare, TextThatIsNotTomlIsSaidSo) {
  EXPECT_EQ(config_difference("[cell\nphi = ", default_cell_config({})),
            "its config.toml is not valid TOML");
}

}  // namespace
}  // namespace dilatant::config_compare_test
