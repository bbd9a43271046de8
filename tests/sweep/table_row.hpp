#pragma once
// One row of a sweep's flowcurves.csv by column name, for the sweep tests.
#include <filesystem>
#include <map>
#include <sstream>
#include <string>

#include "analysis/delimited_text.hpp"
#include "app/cli_runner.hpp"

namespace dilatant::test {

// Row `k` (0 = the first point) of `table`; a column the row lacks is empty.
inline std::map<std::string, std::string> table_row(const std::filesystem::path& table,
                                                    std::size_t k) {
  std::istringstream in(read_text(table));
  std::string line;
  std::getline(in, line);
  const auto head = analysis::split_fields(line, ',');
  for (std::size_t i = 0; i <= k; ++i) std::getline(in, line);
  const auto f = analysis::split_fields(line, ',');
  std::map<std::string, std::string> out;
  for (std::size_t c = 0; c < head.size(); ++c) out[head[c]] = c < f.size() ? f[c] : "";
  return out;
}

}  // namespace dilatant::test
