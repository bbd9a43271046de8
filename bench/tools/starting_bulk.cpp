// dilatant-starting-bulk: the bulk fraction a run's packing begins with,
// against its nominal phi, and the search that the bulk rule of a jam's cold
// start makes (drivers/starting_fraction.hpp, sweep.cold_start_phi = "bulk";
// docs/sweeps.md "Ramps to the jam"). Packings are built as a run builds them
// (same seed, same cell), never sheared: seconds each in the paper's cell.
//
//   dilatant-starting-bulk CONFIG [--set key=value ...]
//                          [--scan LOW,HIGH,STEP] [--targets a,b,...]
//                          [--tolerance 0.001] [--max-packings 12] --out DIR
//
// Writes DIR/scan.csv (phi, phi_bulk_start, seconds: one packing per nominal
// phi of the scan) and DIR/search.csv (target, phi, phi_bulk_start,
// within_tolerance, packings, seconds: one search per target, started from
// CONFIG's phi), each written whole, then renamed.
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "drivers/starting_fraction.hpp"
#include "io/atomic_file.hpp"
#include "io/config.hpp"
#include "io/input_error.hpp"

namespace {

using namespace dilatant;
using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

std::string scan_csv(Config config, const std::vector<double>& scan) {
  std::string csv = "phi,phi_bulk_start,seconds\n";
  const double low = scan[0], high = scan[1], step = scan[2];
  const int n = static_cast<int>(std::floor((high - low) / step + 1e-9));
  for (int k = 0; k <= n; ++k) {
    config.cell()->phi = low + k * step;
    const auto start = Clock::now();
    double bulk = std::numeric_limits<double>::quiet_NaN();  // a phi that does not pack
    try {
      bulk = starting_bulk_fraction(config);
    } catch (const std::runtime_error& e) {
      std::cerr << fmt::format("phi {:.4f}: no packing ({})\n", config.cell()->phi, e.what());
    }
    csv += fmt::format("{:.4f},{:.5f},{:.1f}\n", config.cell()->phi, bulk, seconds_since(start));
    std::cerr << fmt::format("phi {:.4f}: starts at {:.5f}\n", config.cell()->phi, bulk);
  }
  return csv;
}

std::string search_csv(const Config& config, const std::vector<double>& targets, double tolerance,
                       int max_packings) {
  std::string csv = "target,phi,phi_bulk_start,within_tolerance,packings,seconds\n";
  for (const double target : targets) {
    const auto start = Clock::now();
    const StartingFractionMatch m = match_starting_bulk(config, target, tolerance, max_packings);
    csv += fmt::format("{:.4f},{:.4f},{:.5f},{},{},{:.1f}\n", target, m.phi, m.phi_bulk_start,
                       m.within_tolerance, m.tried.size(), seconds_since(start));
    std::cerr << fmt::format("target {:.4f}: phi {:.4f} starts at {:.5f} ({} packings)\n", target,
                             m.phi, m.phi_bulk_start, m.tried.size());
  }
  return csv;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"The bulk fraction a run's packing begins with, and the bulk rule's search"};
  std::string config_file, out;
  std::vector<std::string> overrides;
  std::vector<double> scan, targets;
  double tolerance = 1e-3;
  int max_packings = 12;
  app.add_option("config", config_file, "Run configuration (TOML)")->required();
  app.add_option("--set", overrides, "Override a key: dotted.key=TOML value");
  app.add_option("--scan", scan, "LOW,HIGH,STEP: one packing per nominal phi")
      ->delimiter(',')
      ->expected(3);
  app.add_option("--targets", targets, "Starting bulk fractions to search for")->delimiter(',');
  app.add_option("--tolerance", tolerance, "Search tolerance")->capture_default_str();
  app.add_option("--max-packings", max_packings, "Packings a search may build")
      ->capture_default_str();
  app.add_option("--out", out, "Folder of scan.csv and search.csv")->required();
  CLI11_PARSE(app, argc, argv);
  try {
    const Config config = load_config(config_file, overrides);
    if (!config.cell()) throw InputError(config_file + ": not a shear-cell configuration");
    if (!scan.empty() && !(scan[2] > 0.0 && scan[1] >= scan[0]))
      throw InputError("--scan: needs LOW <= HIGH and STEP > 0");
    if (!(tolerance > 0.0)) throw InputError("--tolerance: must be > 0");
    if (max_packings < 1) throw InputError("--max-packings: must be >= 1");
    std::filesystem::create_directories(out);
    if (!scan.empty())
      write_file_atomically(std::filesystem::path(out) / "scan.csv", scan_csv(config, scan));
    if (!targets.empty())
      write_file_atomically(std::filesystem::path(out) / "search.csv",
                            search_csv(config, targets, tolerance, max_packings));
  } catch (const InputError& e) {
    std::cerr << "dilatant-starting-bulk: " << e.what() << "\n";
    return 2;
  }
  return 0;
}
