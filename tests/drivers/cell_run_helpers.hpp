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

namespace dilatant::test {

// A folder of this process's own for the run called `name`.
inline std::filesystem::path cell_run_dir(const std::string& name) {
  return std::filesystem::temp_directory_path() /
         ("dilatant_" + name + "_" + std::to_string(::getpid()));
}

// Runs the default cell with `overrides` into `dir` (emptied first) and
// returns its summary.json; the folder's other files stay for the caller.
// On one thread unless `overrides` says otherwise: results do not depend on the
// thread count (ShearCellRun.TwoThreadsGiveTheSameBitsAsOne), and ctest runs
// one test per core, so a two-thread cell beside another test would have four
// threads on two cores, each OpenMP barrier then waiting for a thread that is
// not running.
inline nlohmann::json run_cell_in(const std::filesystem::path& dir,
                                  const std::vector<std::string>& overrides) {
  std::filesystem::remove_all(dir);
  std::vector<std::string> one_thread_first = {"solver.threads=1"};
  one_thread_first.insert(one_thread_first.end(), overrides.begin(), overrides.end());
  run_shear_cell(default_cell_config(one_thread_first),
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
//
// How many seeds, and how long (docs/testing.md "Sizing the seed-averaged
// suites"; measured with scripts/seed_scatter.py, 12 seeds of 10 strain of the
// 8 x 5 x 9 cell, the literal model): a test comparing two settings' seed
// means fails beyond 3 combined standard errors, 3 sqrt(2/n) s(T) with n seeds
// averaged over T strain each, s(T) the relative scatter between seeds. It
// catches a relative shift delta at three standard errors when
// n >= 18 s(T)^2 / delta^2. Each run adds 2 strain of transient.
//
// Between walls (lambda 1) s hardly falls beyond a window of 4 strain: s(T) =
// 0.154, 0.167, 0.139, 0.141 for gamma_dot (so eta) over T = 1, 2, 4, 8, and
// 0.251, 0.198, 0.128, 0.145 for P_BL (each seed's packing keeps its own mean;
// s itself is known to +-20% from 12 seeds). So the wall cell's suites average
// over T = 4, and kSeeds = 4 seeds catch shifts of 29% in eta and 27% in P_BL
// at three combined standard errors; seeds beyond that are the only lever. In
// the Lees–Edwards cell s falls as 1/sqrt(T) (0.306, 0.188, 0.132, 0.107:
// s^2 T = 0.07): 4 seeds of T = 4 catch 28% of gamma_dot there.
// A 5% shift would need 141 seeds a setting between walls (about 20
// CPU-minutes a setting), 500 strain in the Lees–Edwards cell: beyond CI; see
// each suite for what it exists to catch.
inline constexpr int kSeeds = 4;
inline constexpr double kSeedWindow = 4.0;
inline constexpr double kSeedTransient = 2.0;

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

// One run per seed 1..seeds of the default cell with `overrides`, each of
// kSeedTransient + window strain (overriding any run length in `overrides`).
inline std::vector<nlohmann::json> run_cell_seeds(const std::string& name,
                                                  const std::vector<std::string>& overrides,
                                                  int seeds = kSeeds, double window = kSeedWindow) {
  std::vector<nlohmann::json> runs;
  for (int seed = 1; seed <= seeds; ++seed) {
    std::vector<std::string> o = overrides;
    o.push_back("run.strain=" + std::to_string(kSeedTransient + window));
    o.push_back("run.transient_strain=" + std::to_string(kSeedTransient));
    o.push_back("cell.seed=" + std::to_string(seed));
    runs.push_back(run_cell_summary(name + "_s" + std::to_string(seed), o));
  }
  return runs;
}

}  // namespace dilatant::test
