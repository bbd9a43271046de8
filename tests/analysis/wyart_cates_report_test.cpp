// The Wyart–Cates report over repeated packings: samples that differ only by
// their seed (a sweep over cell.seed) are fitted one by one and pooled, and
// the scatter of the per-seed fits is the error bar a single fit cannot give.
// On synthetic curves with independent noise per seed, that scatter must match
// the fits' own errors, and the pooled fit must recover the truth.
#include "analysis/wyart_cates_report.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "analysis/wyart_cates_curves.hpp"
#include "analysis/wyart_cates_seeds.hpp"

namespace dilatant::analysis::wyart_cates_report_test {
namespace {

const WyartCatesParameters kTruth{0.64, 0.56, 2.0, 1.3, 2.0, 1.0};
const std::vector<double> kPhis = {0.45, 0.50, 0.53, 0.55, 0.575};
constexpr double kNoise = 0.05;

// `seeds` samples "mu0=0.5 seed=k", each its own draw of the same suspension.
AnalysisInput seeded_input(int seeds) {
  AnalysisInput in;
  in.source = "synthetic";
  in.kind = InputKind::SweepTable;
  in.units = UnitSystem::Paper;
  for (int k = 1; k <= seeds; ++k) {
    const std::string name = "mu0=0.5 seed=" + std::to_string(k);
    for (auto& c : test::curves(kTruth, kPhis, kNoise, 200 + k, 0.01, 100.0, name))
      in.curves.push_back(c);
    in.samples.push_back(name);
  }
  return in;
}

const WyartCatesSample* find(const WyartCatesReport& r, const std::string& name) {
  for (const auto& s : r.samples)
    if (s.sample == name) return &s;
  return nullptr;
}

TEST(WyartCatesSeeds, GroupsAreLabelsThatDifferOnlyInTheirSeed) {
  const auto groups = seed_groups(
      {"mu0=0.5 seed=1", "mu0=1 seed=1", "mu0=0.5 seed=2", "mu0=1", "mu0=0.5 s_c=1e-5 seed=1"});
  ASSERT_EQ(groups.size(), 1u);  // mu0=1 and the s_c one have one seed each
  EXPECT_EQ(groups[0].label, "mu0=0.5");
  EXPECT_EQ(groups[0].members, (std::vector<std::string>{"mu0=0.5 seed=1", "mu0=0.5 seed=2"}));
}

TEST(WyartCatesSeeds, SpreadIsTheMeanSdAndStandardError) {
  const SeedSpread s = seed_spread("phi_m", {1.0, 2.0, 3.0});
  EXPECT_EQ(s.n, 3u);
  EXPECT_DOUBLE_EQ(s.mean, 2.0);
  EXPECT_DOUBLE_EQ(s.sd, 1.0);
  EXPECT_DOUBLE_EQ(s.sem, 1.0 / std::sqrt(3.0));
  EXPECT_TRUE(std::isnan(seed_spread("phi_m", {1.0}).sd));
}

TEST(WyartCatesSeeds, PooledFitRecoversTheTruthAndTheScatterMatchesTheErrors) {
  constexpr int kSeeds = 8;
  const WyartCatesReport r = wyart_cates_report(seeded_input(kSeeds), {});
  ASSERT_EQ(r.samples.size(), kSeeds + 1u);
  const WyartCatesSample* pooled = find(r, "mu0=0.5");
  ASSERT_NE(pooled, nullptr);
  ASSERT_TRUE(pooled->outcome.fit) << pooled->outcome.why_not;
  EXPECT_EQ(pooled->members.size(), static_cast<std::size_t>(kSeeds));
  EXPECT_EQ(pooled->curves, kSeeds * kPhis.size());
  const WyartCatesFit& f = *pooled->outcome.fit;
  EXPECT_LT(std::abs(f.phi_m.value - kTruth.phi_m), 4 * f.phi_m.err);
  EXPECT_LT(std::abs(f.phi_0.value - kTruth.phi_0), 4 * f.phi_0.err);

  double member_err = 0.0;  // the per-seed fits' mean error of phi_m
  for (int k = 1; k <= kSeeds; ++k) {
    const auto* s = find(r, "mu0=0.5 seed=" + std::to_string(k));
    ASSERT_TRUE(s && s->outcome.fit);
    member_err += s->outcome.fit->phi_m.err / kSeeds;
  }
  // Eight times the data: the pooled error near 1/sqrt(8) of one seed's.
  EXPECT_LT(f.phi_m.err, 0.6 * member_err);
  const auto spread = pooled->seed_spreads;
  const auto phi_m = std::find_if(spread.begin(), spread.end(),
                                  [](const SeedSpread& q) { return q.name == "phi_m"; });
  ASSERT_NE(phi_m, spread.end());
  EXPECT_EQ(phi_m->n, static_cast<std::size_t>(kSeeds));
  // Independent noise: the seeds' sd is their fits' error; sd/sigma over 7
  // degrees of freedom lies within 0.42-1.63 at 99%.
  EXPECT_GT(phi_m->sd, 0.35 * member_err);
  EXPECT_LT(phi_m->sd, 1.8 * member_err);
  EXPECT_LT(std::abs(phi_m->mean - f.phi_m.value), 3 * phi_m->sem);

  const auto json = nlohmann::json::parse(wyart_cates_json(r));
  const auto& seeds = json["samples"]["mu0=0.5"]["seeds"];
  EXPECT_EQ(seeds["members"].size(), static_cast<std::size_t>(kSeeds));
  EXPECT_DOUBLE_EQ(seeds["spread"]["phi_m"]["sem"].get<double>(), phi_m->sem);
  EXPECT_FALSE(json["samples"]["mu0=0.5 seed=1"].contains("seeds"));
}

TEST(WyartCatesSeeds, PooledCurvesHoldEveryPointAndOneModelLinePerPhi) {
  const WyartCatesReport r = wyart_cates_report(seeded_input(2), {});
  const std::string csv = wyart_cates_curves_csv(r);
  std::size_t member_data = 0, pooled_data = 0, pooled_model_phis = 0;
  std::string last_model_phi;
  for (std::size_t at = csv.find('\n') + 1; at < csv.size();) {
    const std::size_t end = csv.find('\n', at);
    const std::string line = csv.substr(at, end - at);
    at = end + 1;
    const bool pooled = line.rfind("mu0=0.5,", 0) == 0;
    const std::string rest = line.substr(line.find(',') + 1);
    const std::string phi = rest.substr(0, rest.find(','));
    if (line.find(",data,") != std::string::npos) ++(pooled ? pooled_data : member_data);
    if (pooled && line.find(",model,") != std::string::npos && phi != last_model_phi) {
      ++pooled_model_phis;
      last_model_phi = phi;
    }
  }
  EXPECT_GT(member_data, 0u);
  EXPECT_EQ(pooled_data, member_data);
  EXPECT_EQ(pooled_model_phis, kPhis.size());
}

TEST(WyartCatesSeeds, APooledLabelNeverTakesAnInputSamplesName) {
  AnalysisInput in = seeded_input(2);
  for (auto& c : test::curves(kTruth, kPhis, kNoise, 9, 0.01, 100.0, "mu0=0.5"))
    in.curves.push_back(c);
  in.samples.push_back("mu0=0.5");
  const WyartCatesReport r = wyart_cates_report(in, {});
  ASSERT_NE(find(r, "mu0=0.5 (seeds pooled)"), nullptr);
  EXPECT_EQ(find(r, "mu0=0.5")->members.size(), 0u);
}

}  // namespace
}  // namespace dilatant::analysis::wyart_cates_report_test
