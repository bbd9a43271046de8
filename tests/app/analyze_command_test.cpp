// End-to-end tests of `dilatant analyze` (docs/analysis.md): the real executable
// on the shipped example, on a sweep's flowcurves.csv, without a usable Python,
// and on malformed input (exit 2, one line naming file and line, no results).
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "app/cli_runner.hpp"

namespace dilatant::analyze_command_test {
namespace {

namespace fs = std::filesystem;
using test::read_text;

const fs::path kSource = DILATANT_SOURCE_DIR;
const std::vector<std::string> kTables = {"curves.csv", "points.csv", "fits.json"};
const std::vector<std::string> kPlots = {"flow_curves", "n_vs_phi", "collapse"};

std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string l; std::getline(in, l);) out.push_back(l);
  return out;
}

TEST(AnalyzeCommand, ExampleManifestGivesTablesPlotsAndASummary) {
  test::CliDir dir;
  const fs::path out = dir.path() / "out";
  const auto r = dir.run(
      {"analyze", (kSource / "examples/analysis/manifest.toml").string(), "--out", out.string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const auto& name : kTables) EXPECT_TRUE(fs::is_regular_file(out / name)) << name;
  EXPECT_EQ(lines(read_text(out / "curves.csv")).size(), 1u + 28u);
  const auto fits = nlohmann::json::parse(read_text(out / "fits.json"));
  EXPECT_NEAR(fits["samples"]["D"]["phi_max"].get<double>(), 0.545, 0.005);
  EXPECT_NE(r.out.find("collapse of 4 samples"), std::string::npos) << r.out;
  if (test::matplotlib_available()) {
    EXPECT_EQ(r.err, "");
    for (const auto& plot : kPlots)
      for (const char* ext : {".png", ".svg"})
        EXPECT_GT(fs::file_size(out / (plot + ext)), 1000u) << plot << ext;
  } else {
    EXPECT_NE(r.err.find("plots skipped"), std::string::npos) << r.err;
  }
  for (const auto& e : fs::directory_iterator(out))
    EXPECT_NE(e.path().extension(), ".part") << e.path();
}

TEST(AnalyzeCommand, WithoutPythonThePlotsAreSkippedAndTheTablesWritten) {
  test::CliDir dir;
  const fs::path out = dir.path() / "out";
  const auto r = dir.run({"analyze", (kSource / "examples/analysis/manifest.toml").string(),
                          "--out", out.string(), "--python", "/nonexistent/python3", "-q"});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_NE(r.err.find("plots skipped"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("/nonexistent/python3"), std::string::npos) << r.err;
  EXPECT_EQ(r.out, "") << "--quiet";
  for (const auto& name : kTables) EXPECT_TRUE(fs::is_regular_file(out / name)) << name;
  EXPECT_FALSE(fs::exists(out / "collapse.png"));
}

// A sample whose every point jammed (the s_c 5e-4 ramp of the onset's s_c
// scaling, docs/paper-reproduction.md) has nothing to draw on log axes: its
// panel says so and the other samples' plots are still drawn.
TEST(AnalyzeCommand, ASampleWithOnlyJammedPointsStillGetsItsPlots) {
  if (!test::matplotlib_available()) GTEST_SKIP() << "no matplotlib";
  test::CliDir dir;
  const fs::path out = dir.path() / "out";
  const auto r =
      dir.run({"analyze", (kSource / "tests/analysis/data/sample-all-jammed.csv").string(), "--out",
               out.string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err, "");
  const auto rows = lines(read_text(out / "curves.csv"));
  ASSERT_EQ(rows.size(), 1u + 3u);
  EXPECT_NE(rows[1].find(",jammed,"), std::string::npos) << rows[1];
  for (const auto& plot : kPlots) EXPECT_GT(fs::file_size(out / (plot + ".png")), 1000u) << plot;
}

TEST(AnalyzeCommand, ASweepTableGivesNPerPhiAndMu0) {
  test::CliDir dir;
  const fs::path out = dir.path() / "out";
  const auto r = dir.run({"analyze", (kSource / "tests/analysis/data/flowcurves.csv").string(),
                          "--out", out.string(), "--no-plots"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err, "");
  const auto rows = lines(read_text(out / "curves.csv"));
  ASSERT_EQ(rows.size(), 1u + 4u);
  EXPECT_EQ(rows[1].rfind("mu0=0.1,0.55,", 0), 0u) << rows[1];
  EXPECT_EQ(rows[4].rfind("mu0=0.4,0.58,", 0), 0u) << rows[4];
  EXPECT_NE(rows[4].find(",dst,jammed,"), std::string::npos) << rows[4];
  const auto fits = nlohmann::json::parse(read_text(out / "fits.json"));
  EXPECT_EQ(fits["units"]["viscosity"], "eta_f");
  EXPECT_EQ(fits["kind"], "sweep_table");
}

struct BadInput {
  std::string name;
  std::string data;  // written to data.csv, listed in the manifest
  int line;          // of data.csv in the message
  std::string problem;
};

class AnalyzeCommandBad : public ::testing::TestWithParam<BadInput> {};

TEST_P(AnalyzeCommandBad, ExitsWith2AndOneLineNamingFileAndLine) {
  const BadInput& c = GetParam();
  test::CliDir dir;
  const fs::path data = dir.write("data.csv", c.data);
  const fs::path manifest =
      dir.write("m.toml", "[[curve]]\nfile = \"data.csv\"\nsample = \"A\"\nphi = 0.5\n");
  const fs::path out = dir.path() / "out";
  const auto r = dir.run({"analyze", manifest.string(), "--out", out.string()});
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_NE(r.err.find(data.string() + ":" + std::to_string(c.line) + ": "), std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find(c.problem), std::string::npos) << r.err;
  for (const auto& name : kTables) EXPECT_FALSE(fs::exists(out / name)) << name;
}

INSTANTIATE_TEST_SUITE_P(
    AnalyzeCommand, AnalyzeCommandBad,
    ::testing::Values(BadInput{"MissingColumn", "Shear Rate [1/s],Time [s]\n1,1\n2,2\n3,3\n", 1,
                               "missing column"},
                      BadInput{"TextInANumber", "shear_rate,shear_stress\n1,1\n2,two\n3,3\n", 3,
                               "'two' is not a number"},
                      BadInput{"EmptyFile", "", 1, "empty file"},
                      BadInput{"SinglePoint", "shear_rate,shear_stress\n1,1\n", 2,
                               "only 1 data point"},
                      BadInput{"UnsortedData", "shear_rate,shear_stress\n1,1\n3,3\n2,2\n", 4,
                               "breaks the ascending ramp"},
                      // The point that breaks the ramp is named, not the next one (issue 31).
                      BadInput{"Spike", "shear_rate,shear_stress\n1,1\n2,2\n9,9\n4,4\n5,5\n", 4,
                               "shear stress 9 breaks the ascending ramp"},
                      // A row with a field too many was once read as a point (issue 31).
                      BadInput{"ExtraField", "shear_rate,shear_stress\n1,1\n2,2,7\n3,3\n4,4\n", 3,
                               "3 fields, the header has 2"},
                      BadInput{"ViscosityDisagrees",
                               "shear_rate,shear_stress,viscosity\n1.00,1.00,1.00\n2.00,4.00,2.50\n"
                               "3.00,9.00,3.00\n4.00,16.0,4.00\n",
                               3, "viscosity 2.5 disagrees with shear stress / shear rate = 2"},
                      BadInput{"Infinite", "shear_rate,shear_stress\n1,1\ninf,2\n3,3\n", 3,
                               "not a finite number"}),
    [](const auto& p) { return p.param.name; });

// An export with zero stress at each step's start and a failed reading
// (issue 31): those rows are dropped, the curve analysed, and the count said
// in the summary and in fits.json.
TEST(AnalyzeCommand, RowsWithZeroOrMissingValuesAreDroppedAndCounted) {
  test::CliDir dir;
  std::string rows = read_text(kSource / "examples/analysis/A_0462.csv");
  const auto second = rows.find('\n') + 1;
  rows.insert(second, "0,0,0\n");                        // line 2: a step's start
  rows.insert(rows.find('\n', second + 6) + 1, ",,\n");  // line 4: no reading
  const fs::path data = dir.write("data.csv", rows);
  const fs::path manifest =
      dir.write("m.toml", "[[curve]]\nfile = \"data.csv\"\nsample = \"A\"\nphi = 0.462\n");
  const fs::path out = dir.path() / "out";
  const auto r = dir.run({"analyze", manifest.string(), "--out", out.string(), "--no-plots"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find(data.string() +
                       ": 2 rows dropped (missing value: line 4; zero or negative value: line 2)"),
            std::string::npos)
      << r.out;
  const auto fits = nlohmann::json::parse(read_text(out / "fits.json"));
  EXPECT_EQ(fits["dropped_rows"], 2);
  ASSERT_EQ(fits["dropped"].size(), 1u);
}

// --list shows a rheometer export's steps; the analysis of its manifest says
// which steps it skipped and labels each curve with its step.
TEST(AnalyzeCommand, ListShowsTheStepsAndTheAnalysisNamesThem) {
  test::CliDir dir;
  std::string rows = "Action Name;Shear rate(1/s);Shear stress(Pa)\n";
  for (int k = 0; k < 3; ++k) rows += fmt::format("Pre-shear;50;{}\n", 30 + k);
  for (int k = 1; k <= 6; ++k) rows += fmt::format("Flow Curve Up;{};{}\n", k * k, k * k * 0.5);
  const fs::path data = dir.write("steps.csv", rows);
  auto r = dir.run({"analyze", "--list", data.string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find(data.string() + ": 2 steps"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("hold"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("Flow Curve Up"), std::string::npos) << r.out;
  const fs::path manifest =
      dir.write("m.toml", "[[curve]]\nfile = \"steps.csv\"\nsample = \"A\"\nphi = 0.5\n");
  const fs::path out = dir.path() / "out";
  r = dir.run({"analyze", manifest.string(), "--out", out.string(), "--no-plots"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("skipped: " + data.string() + ": step 1 'Pre-shear' (hold)"),
            std::string::npos)
      << r.out;
  const std::string curves = read_text(out / "curves.csv");
  EXPECT_NE(curves.find(",step,dropped_rows,"), std::string::npos) << curves;
  // A rheometer's curve counts no contacts: no contact onset (rule 8).
  EXPECT_NE(curves.find(",\"2 'Flow Curve Up'\",0,,,\n"), std::string::npos) << curves;
  r = dir.run({"analyze", "--list", data.string(), manifest.string()});
  EXPECT_EQ(r.exit_code, 2);
  r = dir.run({"analyze"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("INPUT is required"), std::string::npos) << r.err;
}

TEST(AnalyzeCommand, RefusesAnInputThatIsNeitherAManifestNorASweepAndBadOptions) {
  test::CliDir dir;
  const fs::path csv = dir.write("rheo.csv", "shear_rate,shear_stress\n1,1\n2,2\n3,3\n");
  auto r = dir.run({"analyze", csv.string(), "--out", (dir.path() / "out").string()});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find(csv.string() + ":1: "), std::string::npos) << r.err;
  r = dir.run({"analyze", (kSource / "examples/analysis/manifest.toml").string(), "--onset-factor",
               "1.0", "--out", (dir.path() / "out").string()});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--onset-factor"), std::string::npos) << r.err;
  r = dir.run({"analyze", (dir.path() / "missing.toml").string()});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("missing.toml"), std::string::npos) << r.err;
}

TEST(AnalyzeCommand, HelpDescribesInputsAndOutputs) {
  test::CliDir dir;
  const auto r = dir.run({"analyze", "--help"});
  EXPECT_EQ(r.exit_code, 0);
  for (const char* word : {"manifest", "flowcurves.csv", "--out", "fits.json", "--no-plots"})
    EXPECT_NE(r.out.find(word), std::string::npos) << word;
}

}  // namespace
}  // namespace dilatant::analyze_command_test
