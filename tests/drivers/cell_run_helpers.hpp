#pragma once
// Runs a small shear cell in a temporary folder and returns its summary.json.
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "drivers/shear_cell_run.hpp"
#include "io/config.hpp"

namespace dilatant::testing {

// A folder of this process's own for the run called `name`.
inline std::filesystem::path cell_run_dir(const std::string& name) {
  return std::filesystem::temp_directory_path() /
         ("dilatant_" + name + "_" + std::to_string(::getpid()));
}

// Runs the default cell with `overrides` into `dir` (emptied first) and
// returns its summary.json; the folder's other files stay for the caller.
inline nlohmann::json run_cell_in(const std::filesystem::path& dir,
                                  const std::vector<std::string>& overrides) {
  std::filesystem::remove_all(dir);
  run_shear_cell(default_cell_config(overrides),
                 CellRunOptions{RunOptions{dir, true}, false, nullptr});
  std::ifstream in(dir / "summary.json");
  return nlohmann::json::parse(in);
}

inline nlohmann::json run_cell_summary(const std::string& name,
                                       const std::vector<std::string>& overrides) {
  const auto dir = cell_run_dir(name);
  auto summary = run_cell_in(dir, overrides);
  std::filesystem::remove_all(dir);
  return summary;
}

// Shear-cell results are compared over several seeds: on small cells one run's
// block error bar understates the run-to-run scatter.
inline constexpr int kSeeds = 4;

struct SeedMean {
  double mean = 0.0;
  double error = 0.0;
};

// Mean over the seeds of summary[key] and its standard error.
inline SeedMean seed_mean(const std::vector<nlohmann::json>& runs, const std::string& key) {
  const double n = double(runs.size());
  SeedMean m;
  double block_variance = 0.0;
  for (const auto& r : runs) {
    m.mean += r[key].get<double>() / n;
    block_variance += std::pow(r[key + "_err"].get<double>(), 2) / (n * n);
  }
  double scatter = 0.0;
  for (const auto& r : runs) scatter += std::pow(r[key].get<double>() - m.mean, 2) / (n - 1.0);
  m.error = std::sqrt(std::max(scatter / n, block_variance));
  return m;
}

// One run per seed 1..kSeeds of the default cell with `overrides`.
inline std::vector<nlohmann::json> run_cell_seeds(const std::string& name,
                                                  const std::vector<std::string>& overrides) {
  std::vector<nlohmann::json> runs;
  for (int seed = 1; seed <= kSeeds; ++seed) {
    std::vector<std::string> o = overrides;
    o.push_back("cell.seed=" + std::to_string(seed));
    runs.push_back(run_cell_summary(name + "_s" + std::to_string(seed), o));
  }
  return runs;
}

}  // namespace dilatant::testing
