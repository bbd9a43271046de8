// End-to-end: `dilatant analyze --model wyart-cates` on a flowcurves.csv drawn
// from the model with noise (written here), its files, summary and plot; then
// `dilatant predict --model` on the fit it wrote; and bad input (exit 2, one
// line, no results).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <random>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "analysis/wyart_cates_model.hpp"
#include "app/cli_runner.hpp"

namespace dilatant::wyart_cates_command_test {
namespace {

namespace fs = std::filesystem;
using test::read_text;

const analysis::WyartCatesParameters kTruth{0.64, 0.56, 2.0, 1.3, 2.0, 1.0};

// A sweep table (the columns `dilatant sweep` writes that the analysis reads):
// phi at each of `phis`, 0.02 to 200 in stress, 5% log-normal noise on the rate.
// With `seeds` > 0, that many packings of each point, labelled in a `sample`
// column as a sweep over cell.seed labels them ("mu0=1 seed=2").
// With `dilation` > 0, the points are drawn at `phis` but written at nominal
// phi + dilation, with `phis` in a phi_bulk column (a wall cell's bulk).
fs::path write_sweep(const fs::path& dir, const std::vector<double>& phis, int seeds = 0,
                     double dilation = 0.0) {
  std::mt19937_64 rng(11);
  std::normal_distribution<double> normal(0.0, 1.0);
  const fs::path file = dir / "flowcurves.csv";
  std::ofstream out(file);
  out << "phi,mu0,shear_stress,gamma_dot,gamma_dot_err,valid,jammed" << (seeds > 0 ? ",sample" : "")
      << (dilation > 0.0 ? ",phi_bulk\n" : "\n");
  for (int seed = 1; seed <= std::max(seeds, 1); ++seed)
    for (const double drawn : phis)
      for (int k = 0; k <= 24; ++k) {
        const double phi = drawn + dilation;
        // Built in a stream: GCC 12 reports a false -Wstringop-overflow on
        // "," + std::string here (GCC bug 105329).
        std::ostringstream tail;
        if (seeds > 0) tail << ",mu0=1 seed=" << seed;
        if (dilation > 0.0) tail << "," << drawn;
        const std::string sample = tail.str();
        const double sigma = 0.02 * std::pow(10.0, k / 6.0);
        const double eta = analysis::wyart_cates_viscosity(kTruth, drawn, sigma);
        if (!std::isfinite(eta)) {
          out << phi << ",1," << sigma << ",0,,true,true" << sample << "\n";
          continue;
        }
        const double rate = sigma / eta * std::exp(0.05 * normal(rng));
        out << phi << ",1," << sigma << "," << rate << "," << 0.05 * rate << ",true,false" << sample
            << "\n";
      }
  return file;
}

TEST(WyartCatesCommand, AnalyzeFitsWritesTheFilesAndPredictAnswersFromThem) {
  test::CliDir dir;
  const fs::path input = write_sweep(dir.path(), {0.45, 0.50, 0.53, 0.55, 0.575});
  const fs::path out = dir.path() / "out";
  const auto r =
      dir.run({"analyze", input.string(), "--out", out.string(), "--model", "wyart-cates"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("Wyart-Cates fit (alpha 2 fixed, beta 1 fixed)"), std::string::npos)
      << r.out;
  for (const char* name : {"wyart_cates.json", "wyart_cates_curves.csv", "wyart_cates_map.csv",
                           "curves.csv", "fits.json"})
    EXPECT_TRUE(fs::is_regular_file(out / name)) << name;
  const auto j = nlohmann::json::parse(read_text(out / "wyart_cates.json"));
  const auto& s = j["samples"]["mu0=1"];
  ASSERT_TRUE(s["fitted"].get<bool>()) << s.dump();
  for (const auto& [key, truth] : {std::pair{"phi_0", kTruth.phi_0},
                                   {"phi_m", kTruth.phi_m},
                                   {"sigma_star", kTruth.sigma_star},
                                   {"A", kTruth.A}})
    EXPECT_LT(std::abs(s[key].get<double>() - truth),
              4 * s[std::string(key) + "_err"].get<double>())
        << key;
  EXPECT_TRUE(s["alpha_err"].is_null());
  EXPECT_EQ(s["alpha_source"], "fixed");
  EXPECT_NEAR(s["dst"]["phi_dst"].get<double>(), analysis::dst_onset(kTruth).phi, 0.002);
  if (test::matplotlib_available()) {
    EXPECT_GT(fs::file_size(out / "wyart_cates.png"), 1000u) << r.err;
  }

  const std::string model = (out / "wyart_cates.json").string();
  const auto p = dir.run({"predict", "--model", model, "--phi", "0.55", "--stress", "5", "--json"});
  ASSERT_EQ(p.exit_code, 0) << p.err;
  const auto answer = nlohmann::json::parse(p.out);
  EXPECT_EQ(answer["source"], "wyart-cates fit");
  EXPECT_EQ(answer["phi_basis"], "nominal");  // the table has no phi_bulk
  EXPECT_EQ(answer["regime"], "dst");
  EXPECT_EQ(answer["state"], "turns_back");
  const auto text = dir.run({"predict", "--model", model, "--phi", "0.50"});
  EXPECT_EQ(text.exit_code, 0) << text.err;
  EXPECT_EQ(text.out.rfind("cst (phi 0.5", 0), 0u) << text.out;
  EXPECT_NE(text.out.find("source: Wyart-Cates fit"), std::string::npos) << text.out;
  // The tables' answer names its source too (mu0 0.35: no bulk flow curve).
  const auto table = dir.run({"predict", "--mu0", "0.35", "--phi", "0.55", "--json"});
  EXPECT_EQ(nlohmann::json::parse(table.out)["source"], "sediment table") << table.err;

  // A later analysis without the model leaves no stale fit to be drawn.
  const auto again =
      dir.run({"analyze", input.string(), "--out", out.string(), "-q", "--no-plots"});
  ASSERT_EQ(again.exit_code, 0) << again.err;
  EXPECT_FALSE(fs::exists(out / "wyart_cates.json"));
  EXPECT_FALSE(fs::exists(out / "wyart_cates.png"));
}

TEST(WyartCatesCommand, SeedsAreFittedAlonePooledAndPredictAnswersFromThePool) {
  test::CliDir dir;
  const fs::path input = write_sweep(dir.path(), {0.45, 0.50, 0.53, 0.55, 0.575}, 3);
  const fs::path out = dir.path() / "out";
  const auto r = dir.run(
      {"analyze", input.string(), "--out", out.string(), "--model", "wyart-cates", "--no-plots"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("the 3 seeds pooled; their own fits: phi_0 "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("(n=3)"), std::string::npos) << r.out;
  const auto j = nlohmann::json::parse(read_text(out / "wyart_cates.json"));
  for (const char* name : {"mu0=1 seed=1", "mu0=1 seed=2", "mu0=1 seed=3", "mu0=1"})
    EXPECT_TRUE(j["samples"][name]["fitted"].get<bool>()) << name;
  EXPECT_EQ(j["samples"]["mu0=1"]["seeds"]["spread"]["phi_m"]["n"], 3);

  // No --sample: the pooled fit answers, and says so.
  const std::string model = (out / "wyart_cates.json").string();
  const auto p = dir.run({"predict", "--model", model, "--phi", "0.50", "--json"});
  ASSERT_EQ(p.exit_code, 0) << p.err;
  const auto pooled = nlohmann::json::parse(p.out);
  EXPECT_EQ(pooled["sample"], "mu0=1");
  // Its boundaries' errors are at least the seeds' standard errors.
  const auto& spread = j["samples"]["mu0=1"]["seeds"]["spread"];
  for (const char* key : {"phi_0", "phi_m", "phi_dst"})
    EXPECT_GE(pooled[std::string(key) + "_err"].get<double>(), spread[key]["sem"].get<double>())
        << key;
  EXPECT_EQ(pooled["errors"], "the larger of the pooled fit's and the seeds' standard error");
  const auto one =
      dir.run({"predict", "--model", model, "--phi", "0.50", "--sample", "mu0=1 seed=2", "--json"});
  ASSERT_EQ(one.exit_code, 0) << one.err;
  EXPECT_EQ(nlohmann::json::parse(one.out)["sample"], "mu0=1 seed=2");
}

// A table with phi_bulk is fitted in it (the truth comes back although the
// nominal phi is 0.01 higher), and predict reads --phi as a bulk fraction;
// --wc-phi nominal fits the nominal phi, and phi_m moves up by the dilation.
TEST(WyartCatesCommand, ASweepsMeasuredBulkFractionIsWhatIsFitted) {
  test::CliDir dir;
  const fs::path input = write_sweep(dir.path(), {0.45, 0.50, 0.53, 0.55, 0.575}, 0, 0.01);
  const fs::path out = dir.path() / "out";
  const auto r = dir.run({"analyze", input.string(), "--out", out.string(), "--model",
                          "wyart-cates", "--no-plots", "-q"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(read_text(out / "wyart_cates.json"));
  EXPECT_EQ(j["settings"]["phi"], "auto");
  const auto& s = j["samples"]["mu0=1"];
  ASSERT_TRUE(s["fitted"].get<bool>()) << s.dump();
  EXPECT_EQ(s["phi_basis"], "bulk");
  EXPECT_LT(std::abs(s["phi_m"].get<double>() - kTruth.phi_m), 4 * s["phi_m_err"].get<double>());
  const auto text =
      dir.run({"predict", "--model", (out / "wyart_cates.json").string(), "--phi", "0.50"});
  EXPECT_EQ(text.out.rfind("cst (bulk phi 0.5", 0), 0u) << text.out << text.err;

  const fs::path nominal = dir.path() / "nominal";
  const auto n = dir.run({"analyze", input.string(), "--out", nominal.string(), "--model",
                          "wyart-cates", "--wc-phi", "nominal", "--no-plots", "-q"});
  ASSERT_EQ(n.exit_code, 0) << n.err;
  const auto jn = nlohmann::json::parse(read_text(nominal / "wyart_cates.json"));
  const auto& sn = jn["samples"]["mu0=1"];
  ASSERT_TRUE(sn["fitted"].get<bool>()) << sn.dump();
  EXPECT_EQ(sn["phi_basis"], "nominal");
  EXPECT_NEAR(sn["phi_m"].get<double>() - s["phi_m"].get<double>(), 0.01, 0.002);
}

TEST(WyartCatesCommand, DataThatCannotBeFittedExitTwoWithTheReason) {
  test::CliDir dir;
  const fs::path input = write_sweep(dir.path(), {0.53});
  const fs::path out = dir.path() / "out";
  const auto r =
      dir.run({"analyze", input.string(), "--out", out.string(), "--model", "wyart-cates"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("no sample could be fitted (mu0=1: flowing points at 1 volume fraction"),
            std::string::npos)
      << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_FALSE(fs::exists(out));
}

TEST(WyartCatesCommand, BadOptionsExitTwoWithOneLine) {
  test::CliDir dir;
  const fs::path input = write_sweep(dir.path(), {0.45, 0.50});
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
      {{"analyze", input.string(), "--model", "wyart"}, "--model: wyart not in {wyart-cates}"},
      {{"analyze", input.string(), "--fit-beta"}, "--fit-beta requires --model"},
      {{"analyze", input.string(), "--model", "wyart-cates", "--beta", "0"},
       "--beta = 0: must be in (0, 20)"},
      {{"predict", "--model", input.string(), "--phi", "0.5"}, "not a Wyart-Cates fit"},
      {{"predict", "--phi", "0.5", "--stress", "2"}, "--stress requires --model"},
      {{"analyze", input.string(), "--model", "wyart-cates", "--wc-phi", "sideways"}, "--wc-phi"},
      {{"analyze", input.string(), "--wc-phi", "bulk"}, "--wc-phi requires --model"},
      {{"analyze", input.string(), "--model", "wyart-cates", "--wc-weights", "heavy"},
       "--wc-weights"},
  };
  for (const auto& [args, message] : cases) {
    const auto r = dir.run(args);
    EXPECT_EQ(r.exit_code, 2) << args[1];
    EXPECT_NE(r.err.find(message), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  }
}

}  // namespace
}  // namespace dilatant::wyart_cates_command_test
