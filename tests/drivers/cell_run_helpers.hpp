#pragma once
// Runs a small shear cell in a temporary folder and returns its summary.json.
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "drivers/shear_cell_run.hpp"
#include "io/config.hpp"

namespace dilatant::testing {

inline nlohmann::json run_cell_summary(const std::string& name,
                                       const std::vector<std::string>& overrides) {
  const auto dir = std::filesystem::temp_directory_path() /
                   ("dilatant_" + name + "_" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  run_shear_cell(default_cell_config(overrides),
                 CellRunOptions{RunOptions{dir, true}, false, nullptr});
  std::ifstream in(dir / "summary.json");
  auto summary = nlohmann::json::parse(in);
  std::filesystem::remove_all(dir);
  return summary;
}

}  // namespace dilatant::testing
