#include "analysis/wyart_cates_seeds.hpp"

#include <map>
#include <sstream>

#include "measure/sample_mean.hpp"

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
  const SampleMean m = sample_mean(values);
  return {std::move(name), m.n, m.mean, m.sd, m.sem};
}

}  // namespace dilatant::analysis
