// Every configuration shipped in examples/ loads: the docs' figures are made
// from them, so a key renamed or a range tightened must fail here, not hours
// into scripts/docs-paper.sh. Sweep files are expanded into their points, each
// point validated as a run configuration.
#include <gtest/gtest.h>
#include <toml++/toml.h>

#include <filesystem>
#include <set>
#include <string>
#include <vector>

#include "io/config.hpp"
#include "sweep/sweep_plan.hpp"

namespace dilatant::examples_test {
namespace {

namespace fs = std::filesystem;

const fs::path kExamples = fs::path(DILATANT_SOURCE_DIR) / "examples";

// Folders of sweep files; every other .toml is a run configuration, except the
// analysis manifest, which tests/analysis reads.
const std::set<std::string> kSweepFolders = {"paper", "sweep", "laws"};
const std::set<std::string> kSweepFiles = {
    "jamming/shear-jamming.toml", "jamming/shear-jamming-refine.toml", "cluster/scaling.toml"};
const std::set<std::string> kNotConfigs = {"analysis/manifest.toml"};

// A refinement (sweep.refines) of a paper sweep refines the ramps in
// out/paper/NAME, which a fresh clone has not run: it is checked against the
// ramps' committed sweep.toml (docs/paper-reproduction/NAME/, copied by
// scripts/docs-paper.sh), so its configuration must be theirs but for lambda.
std::vector<std::string> refined_ramp_copy(const fs::path& file) {
  const toml::table t = toml::parse_file(file.string());
  const auto refines = t["sweep"]["refines"].value<std::string>();
  if (!refines) return {};
  const fs::path copy =
      fs::path(DILATANT_SOURCE_DIR) / "docs" / "paper-reproduction" / fs::path(*refines).filename();
  return {"sweep.refines=\"" + copy.generic_string() + "\""};
}

TEST(Examples, EveryConfigurationLoads) {
  int runs = 0, sweeps = 0;
  for (const auto& entry : fs::recursive_directory_iterator(kExamples)) {
    if (entry.path().extension() != ".toml") continue;
    const fs::path relative = fs::relative(entry.path(), kExamples);
    if (kNotConfigs.count(relative.generic_string()) != 0) continue;
    SCOPED_TRACE(relative.generic_string());
    const std::string folder = relative.begin()->string();
    if (kSweepFolders.count(folder) != 0 || kSweepFiles.count(relative.generic_string()) != 0) {
      sweep::SweepPlan plan;
      EXPECT_NO_THROW(plan = sweep::load_sweep(entry.path(), refined_ramp_copy(entry.path())));
      EXPECT_FALSE(plan.points.empty());
      ++sweeps;
    } else {
      EXPECT_NO_THROW(load_config(entry.path(), {}));
      ++runs;
    }
  }
  // The paper's five sweeps and the shear-cell, incline and pile runs at least.
  EXPECT_GE(sweeps, 5);
  EXPECT_GE(runs, 4);
}

}  // namespace
}  // namespace dilatant::examples_test
