// The table of configuration keys (io/config_keys.hpp) drives parsing, the
// resolved config and --help: every key appears in each, once, and its
// default is accepted by its own range.
#include "io/config_keys.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <set>
#include <string>
#include <vector>

#include "io/io_test_files.hpp"

namespace dilatant::config_keys_test {
namespace {

using ::testing::HasSubstr;

constexpr const char* kMinimalCell = "[cell]\n";
constexpr const char* kMinimalScene = "[scene]\nparticles = \"p.csv\"\n[run]\ntime = 1.0\n";

Config parse(const char* text) { return parse_config(text, "t.toml", "/base", {}); }

TEST(ConfigKeys, EveryKeyIsDescribedOnceInAKnownSection) {
  std::set<std::string> seen;
  for (const ConfigKey& k : config_keys()) {
    EXPECT_TRUE(is_config_section(k.section)) << k.dotted();
    EXPECT_TRUE(seen.insert(k.dotted()).second) << k.dotted() << " twice";
    EXPECT_FALSE(k.doc.empty()) << k.dotted();
    EXPECT_FALSE(k.type.empty()) << k.dotted();
    EXPECT_EQ(find_config_key(k.section, k.name), &k);
  }
  EXPECT_EQ(
      seen.size(),
      61u);  // 16 cell, 6 scene, 8 sediment, 1 + 6 + 6 + 12 + 6: a new key is a deliberate change
}

// The defaults (the structs' initialisers) lie in their own ranges: the
// smallest configs of both modes load, and resolve to exactly the keys of their mode.
TEST(ConfigKeys, DefaultsAreValidAndTheResolvedConfigHasTheKeysOfItsMode) {
  for (const char* text : {kMinimalCell, kMinimalScene, "[sediment]\n"}) {
    const Config c = parse(text);
    const RunMode mode = run_mode(c);
    for (const ConfigKey& k : config_keys()) {
      const bool present = c.resolved.at_path(k.dotted()).node() != nullptr;
      EXPECT_EQ(present, k.applies_to(mode)) << k.dotted() << " in " << mode_name(mode);
    }
  }
}

TEST(ConfigKeys, ResolvedCellConfigShowsTheFluidViscosityItUses) {
  const Config c = parse_config("[cell]\n[fluid]\nlambda = 25.0\n", "t.toml", "/base", {});
  EXPECT_DOUBLE_EQ(c.fluid_viscosity(), 1.0 / 25.0);  // sqrt(tau rho_p) R / lambda, all 1
  const std::string text = resolved_toml(c);
  EXPECT_THAT(text, HasSubstr("# eta_f = 0.04  (derived:"));
  // ... as a comment: the resolved config loads back to the same configuration.
  EXPECT_EQ(parse_config(text, "config.toml", "/x", {}).resolved, c.resolved);
  // tau, rho_p and R enter as symbols: eta_f = sqrt(4 * 2) * 0.5 / 2.
  const Config d = parse_config(
      "[cell]\nshear_stress = 4.0\nradius_min = 0.4\nradius_max = 0.5\n[particles]\n"
      "density = 2.0\n[fluid]\nlambda = 2.0\n",
      "t.toml", "/base", {});
  EXPECT_DOUBLE_EQ(d.fluid_viscosity(), std::sqrt(8.0) * 0.5 / 2.0);
  // A scene states its own.
  const Config s =
      parse_config(std::string(kMinimalScene) + "[fluid]\neta_f = 0.003\n", "t.toml", "/base", {});
  EXPECT_EQ(s.fluid_viscosity(), 0.003);
}

TEST(ConfigKeys, HelpListsEveryKeyWithItsDefault) {
  const std::string help = config_keys_help();
  for (const ConfigKey& k : config_keys()) {
    EXPECT_THAT(help, HasSubstr("  " + std::string(k.name) + " = ")) << k.dotted();
  }
  EXPECT_THAT(help, HasSubstr("phi = 0.58"));
  EXPECT_THAT(help, HasSubstr("relaxation = 1.3"));
  EXPECT_THAT(help, HasSubstr("eta_f = 0.0\n      fluid viscosity"));
  EXPECT_THAT(help, HasSubstr("([scene] only)"));
}

// A key of the other run mode is an error naming the key and where it was
// written, never silently ignored.
TEST(ConfigKeys, KeysOfTheOtherModeAreErrors) {
  struct Case {
    std::string toml;
    std::vector<std::string> overrides;
    std::vector<std::string> expected;
  };
  const std::vector<Case> cases = {
      {"[cell]\n[fluid]\neta_f = 0.1\n",
       {},
       {"test.toml:3: fluid.eta_f: not a key of a [cell] run",
        "derives eta_f = sqrt(tau rho_p) R / fluid.lambda"}},
      {"[cell]\n", {"fluid.eta_f=0.1"}, {"--set fluid.eta_f: not a key of a [cell] run"}},
      {"[scene]\nparticles = \"p.csv\"\n[run]\ntime = 1.0\n[fluid]\nlambda = 3.0\n",
       {},
       {"fluid.lambda: not a key of a [scene] run (it belongs to [cell] runs)"}},
      {"[cell]\n[run]\ntime = 3.0\n", {}, {"run.time: not a key of a [cell] run"}},
      {"[scene]\nparticles = \"p.csv\"\n[run]\ntime = 1.0\nstrain = 2.0\n",
       {},
       {"run.strain: not a key of a [scene] run"}},
      {"[scene]\nparticles = \"p.csv\"\n[run]\ntime = 1.0\noutput_interval = 0.1\n",
       {},
       {"run.output_interval: not a key of a [scene] run"}},
      {"[scene]\nparticles = \"p.csv\"\n[run]\ntime = 1.0\n",
       {"solver.max_displacement=0.01"},
       {"--set solver.max_displacement: not a key of a [scene] run"}},
  };
  for (const Case& c : cases) {
    const std::string message =
        test::input_error_message([&] { parse_config(c.toml, "test.toml", "/base", c.overrides); });
    for (const auto& part : c.expected) EXPECT_THAT(message, HasSubstr(part)) << c.toml;
    EXPECT_THAT(message, ::testing::Not(HasSubstr("\n")));
  }
}

}  // namespace
}  // namespace dilatant::config_keys_test
