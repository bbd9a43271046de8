#include "analysis/analysis_input.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "analysis/delimited_text.hpp"
#include "io/input_error.hpp"

namespace dilatant::analysis {

AnalysisInput load_analysis_input(const std::filesystem::path& path) {
  if (path.extension() == ".toml") return read_manifest(path);
  const auto lines = read_text_lines(path);
  if (!lines.empty()) {
    const auto fields = split_fields(lines[0], ',');
    const auto has = [&](std::string_view name) {
      return std::find(fields.begin(), fields.end(), name) != fields.end();
    };
    if (has("phi") && has("mu0") && has("shear_stress") && has("gamma_dot"))
      return read_sweep_table(path);
  }
  throw InputError(fmt::format(
      "{}:1: neither a manifest (.toml) nor a sweep's flowcurves.csv (a header with phi, mu0, "
      "shear_stress, gamma_dot, valid, jammed); to analyse rheometer files, list them in a "
      "manifest (docs/analysis.md)",
      path.string()));
}

}  // namespace dilatant::analysis
