#include "analysis/wyart_cates_seeds.hpp"

#include <cmath>
#include <limits>
#include <map>
#include <sstream>

namespace dilatant::analysis {
namespace {

constexpr std::string_view kSeedToken = "seed=";

// The label without its seed token, or empty when it has none.
std::string without_seed(const std::string& label) {
  std::istringstream words(label);
  std::string word, rest;
  bool found = false;
  while (words >> word) {
    if (word.rfind(kSeedToken, 0) == 0) {
      found = true;
      continue;
    }
    rest += (rest.empty() ? "" : " ") + word;
  }
  return found ? rest : std::string();
}

}  // namespace

std::vector<SeedGroup> seed_groups(const std::vector<std::string>& samples) {
  std::vector<SeedGroup> groups;
  std::map<std::string, std::size_t> index;
  for (const std::string& s : samples) {
    const std::string label = without_seed(s);
    if (label.empty()) continue;
    auto [it, added] = index.try_emplace(label, groups.size());
    if (added) groups.push_back({label, {}});
    groups[it->second].members.push_back(s);
  }
  std::erase_if(groups, [](const SeedGroup& g) { return g.members.size() < 2; });
  return groups;
}

SeedSpread seed_spread(std::string name, const std::vector<double>& values) {
  SeedSpread s;
  s.name = std::move(name);
  s.n = values.size();
  if (s.n == 0) {
    s.mean = s.sd = s.sem = std::numeric_limits<double>::quiet_NaN();
    return s;
  }
  for (const double v : values) s.mean += v;
  s.mean /= static_cast<double>(s.n);
  if (s.n < 2) {
    s.sd = s.sem = std::numeric_limits<double>::quiet_NaN();
    return s;
  }
  double ss = 0.0;
  for (const double v : values) ss += (v - s.mean) * (v - s.mean);
  s.sd = std::sqrt(ss / static_cast<double>(s.n - 1));
  s.sem = s.sd / std::sqrt(static_cast<double>(s.n));
  return s;
}

}  // namespace dilatant::analysis
