// End-to-end tests of the `dilatant` executable (README "Using it"): a real process is run
// on files written to a private temporary directory, and its exit code, stderr
// and output folder are checked. Exit codes: 0 success, 2 bad input with exactly
// one line on stderr naming the culprit, 1 any other failure.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "app/cli_runner.hpp"

namespace dilatant::cli_test {
namespace {

namespace fs = std::filesystem;

// Two spheres (r = 0.5, density 2) on the floor z = 0: sphere 0 at rest, sphere 1
// launched sliding along x, so the trajectory is not trivially constant.
constexpr const char* kSceneToml = R"(# two spheres on a floor
[scene]
particles = "particles.csv"
gravity = [0.0, 0.0, -9.81]
trajectory_interval = 0.01

[[scene.planes]]
point = [0.0, 0.0, 0.0]
normal = [0.0, 0.0, 1.0]

[particles]
density = 2.0

[friction]
law = "stribeck"
mu0 = 0.1

[solver]
dt = 1e-3
tolerance = 1e-10

[run]
time = 0.05
)";

constexpr const char* kParticlesCsv =
    "id,x,y,z,r,vx\n"
    "0,0.0,0.0,0.5,0.5,0.0\n"
    "1,2.0,0.0,0.5,0.5,0.5\n";

constexpr double kRadius = 0.5;
constexpr double kDensity = 2.0;
constexpr double kGravity = 9.81;

const std::vector<std::string> kResultFiles = {"config.toml", "summary.json", "trajectory.csv",
                                               "contacts.csv", "timeseries.csv"};

// `text` with the first `from` replaced by `to`; "" when `from` is absent (the
// test then fails on the empty config, which flags a broken case set-up).
std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  if (at == std::string::npos) return "";
  return text.replace(at, from.size(), to);
}

// The 1-based number of the line of `text` holding `needle` (0 if none).
int line_of(const std::string& text, const std::string& needle) {
  const auto at = text.find(needle);
  if (at == std::string::npos) return 0;
  return 1 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<long>(at), '\n'));
}

using test::read_text;
using test::RunResult;
using TempDir = test::CliDir;

std::vector<std::string> split(const std::string& s, char sep) {
  std::vector<std::string> parts;
  std::string part;
  std::istringstream in(s);
  while (std::getline(in, part, sep)) parts.push_back(part);
  return parts;
}

std::vector<fs::path> part_files(const fs::path& dir) {
  std::vector<fs::path> parts;
  if (!fs::exists(dir)) return parts;
  for (const auto& e : fs::recursive_directory_iterator(dir)) {
    if (e.path().extension() == ".part") parts.push_back(e.path());
  }
  return parts;
}

// ---------------------------------------------------------------------------
// 1. A valid scene: exit 0, every result file, reproducible from config.toml.

TEST(Cli, ValidSceneWritesEveryResultAndItsConfigReproducesTheRun) {
  TempDir dir;
  const fs::path config = dir.write("scene.toml", kSceneToml);
  dir.write("particles.csv", kParticlesCsv);
  const fs::path out = dir.path() / "out";

  const RunResult r = dir.run({"run", config.string(), "--out", out.string()});
  ASSERT_EQ(r.exit_code, 0) << "stderr: " << r.err;
  EXPECT_EQ(r.err, "") << "a converged valid run writes nothing to stderr";
  for (const auto& name : kResultFiles) {
    EXPECT_TRUE(fs::is_regular_file(out / name)) << name << " missing in " << out;
  }
  EXPECT_TRUE(part_files(out).empty()) << "left-over " << part_files(out).front();

  // summary.json parses and reports the run.
  const nlohmann::json summary = nlohmann::json::parse(read_text(out / "summary.json"), nullptr,
                                                       /*allow_exceptions=*/false);
  ASSERT_FALSE(summary.is_discarded()) << "summary.json is not valid JSON";
  ASSERT_TRUE(summary.contains("steps"));
  ASSERT_TRUE(summary["steps"].is_number_integer());
  EXPECT_GT(summary["steps"].get<long>(), 0);
  ASSERT_TRUE(summary.contains("version"));
  ASSERT_TRUE(summary["version"].is_string());
  EXPECT_FALSE(summary["version"].get<std::string>().empty());

  // contacts.csv: both spheres touch plane 0 (j = -1) with N = m g.
  const auto lines = split(read_text(out / "contacts.csv"), '\n');
  ASSERT_FALSE(lines.empty());
  EXPECT_EQ(lines[0], "i,j,normal_force,tangential_force,sliding_speed,sommerfeld,regime");
  const double mg =
      4.0 / 3.0 * std::numbers::pi * kRadius * kRadius * kRadius * kDensity * kGravity;
  bool resting_found = false;
  bool sliding_found = false;
  for (std::size_t k = 1; k < lines.size(); ++k) {
    if (lines[k].empty()) continue;
    const auto fields = split(lines[k], ',');
    ASSERT_EQ(fields.size(), 7u) << "contacts.csv row: " << lines[k];
    if (fields[0] == "0") {
      resting_found = true;
      EXPECT_EQ(fields[1], "-1") << "sphere 0 rests on plane 0: " << lines[k];
      const double n = std::stod(fields[2]);
      EXPECT_NEAR(n, mg, 1e-6 * mg) << lines[k];
    } else if (fields[0] == "1") {
      sliding_found = true;
      EXPECT_EQ(fields[1], "-1") << "sphere 1 slides on plane 0: " << lines[k];
    }
  }
  EXPECT_TRUE(resting_found) << "no contact of sphere 0 in contacts.csv";
  EXPECT_TRUE(sliding_found) << "no contact of sphere 1 in contacts.csv";

  // The resolved config is complete: re-running it gives the same results.
  const fs::path out2 = dir.path() / "out2";
  const RunResult r2 =
      dir.run({"run", (out / "config.toml").string(), "--out", out2.string(), "--quiet"});
  ASSERT_EQ(r2.exit_code, 0) << "stderr: " << r2.err;
  const std::string trajectory = read_text(out / "trajectory.csv");
  EXPECT_GT(split(trajectory, '\n').size(), 2u) << "trajectory.csv has no frames";
  EXPECT_EQ(trajectory, read_text(out2 / "trajectory.csv"))
      << "re-running out/config.toml gave a different trajectory.csv";
  EXPECT_EQ(read_text(out / "contacts.csv"), read_text(out2 / "contacts.csv"));
}

// ---------------------------------------------------------------------------
// 2. --set overrides reach the resolved config.

TEST(Cli, SetOverridesAKeyAndShowsInTheResolvedConfig) {
  TempDir dir;
  const fs::path config = dir.write("scene.toml", kSceneToml);
  dir.write("particles.csv", kParticlesCsv);
  const fs::path out = dir.path() / "out";
  const RunResult r =
      dir.run({"run", config.string(), "--set", "friction.mu0=0.25", "--out", out.string()});
  ASSERT_EQ(r.exit_code, 0) << "stderr: " << r.err;
  const std::string resolved = read_text(out / "config.toml");
  EXPECT_NE(resolved.find("mu0 = 0.25"), std::string::npos) << resolved;
  EXPECT_EQ(resolved.find("mu0 = 0.1\n"), std::string::npos) << resolved;
}

TEST(Cli, SetAcceptsABareWordAsAString) {
  TempDir dir;
  const fs::path config = dir.write("scene.toml", kSceneToml);
  dir.write("particles.csv", kParticlesCsv);
  const fs::path out = dir.path() / "out";
  const RunResult r =
      dir.run({"run", config.string(), "--set", "friction.law=coulomb", "--out", out.string()});
  ASSERT_EQ(r.exit_code, 0) << "stderr: " << r.err;
  const std::string resolved = read_text(out / "config.toml");
  EXPECT_NE(resolved.find("coulomb"), std::string::npos) << resolved;
  EXPECT_EQ(resolved.find("stribeck"), std::string::npos) << resolved;
}

// ---------------------------------------------------------------------------
// 3. Bad input: exit 2, one line on stderr naming the culprit, no results.

struct BadInput {
  std::string name;
  std::string config;                     // written to scene.toml
  std::string particles = kParticlesCsv;  // written to particles.csv
  std::vector<std::string> args;          // after "run"; "{config}" stands for scene.toml's path
  std::vector<std::string> culprits;      // each must appear in the message
};

std::vector<BadInput> bad_inputs() {
  const std::string scene = kSceneToml;
  std::vector<BadInput> cases;
  const std::vector<std::string> run_config = {"{config}"};

  {
    const std::string c = replaced(scene, "mu0 = 0.1\n", "mu0 = 0.1\nmuu = 0.2\n");
    cases.push_back({"UnknownKey", c, kParticlesCsv, run_config, {"scene.toml", "friction.muu"}});
  }
  cases.push_back({"WrongType",
                   replaced(scene, "density = 2.0", "density = \"heavy\""),
                   kParticlesCsv,
                   run_config,
                   {"scene.toml", "particles.density"}});
  cases.push_back({"NegativeRadiusInCsv",
                   scene,
                   "id,x,y,z,r\n0,0.0,0.0,0.5,0.5\n1,2.0,0.0,0.5,-0.5\n",
                   run_config,
                   {"particles.csv:3"}});
  cases.push_back({"TextInANumberInCsv",
                   scene,
                   "id,x,y,z,r\n0,0.0,0.0,0.5,0.5\n1,2.0,abc,0.5,0.5\n",
                   run_config,
                   {"particles.csv:3", "abc"}});
  cases.push_back({"OverlappingParticles",
                   scene,
                   "id,x,y,z,r\n31,0.0,0.0,0.5,0.5\n47,0.6,0.0,0.5,0.5\n",
                   run_config,
                   {"particles.csv", "31", "47"}});
  cases.push_back({"SpherePenetratingAPlane",
                   scene,
                   "id,x,y,z,r\n31,0.0,0.0,0.5,0.5\n47,2.0,0.0,0.3,0.5\n",
                   run_config,
                   {"47", "scene.planes[0]"}});
  cases.push_back({"ZeroPlaneNormal",
                   replaced(scene, "normal = [0.0, 0.0, 1.0]", "normal = [0.0, 0.0, 0.0]"),
                   kParticlesCsv,
                   run_config,
                   {"scene.toml", "scene.planes[0].normal"}});
  cases.push_back({"CellPhiTooLarge",
                   "[cell]\nphi = 0.8\n",
                   kParticlesCsv,
                   run_config,
                   {"scene.toml", "cell.phi"}});
  cases.push_back({"MissingParticlesFile",
                   replaced(scene, "particles = \"particles.csv\"", "particles = \"missing.csv\""),
                   kParticlesCsv,
                   run_config,
                   {"missing.csv"}});
  cases.push_back({"BothCellAndScene",
                   scene + "\n[cell]\nphi = 0.5\n",
                   kParticlesCsv,
                   run_config,
                   {"scene.toml", "cell"}});
  cases.push_back({"SetWithoutEquals",
                   scene,
                   kParticlesCsv,
                   {"{config}", "--set", "friction.mu0"},
                   {"--set", "friction.mu0"}});
  cases.push_back({"SetOfAnUnknownKey",
                   scene,
                   kParticlesCsv,
                   {"{config}", "--set", "friction.nope=1"},
                   {"friction.nope"}});
  cases.push_back({"SetOfAWrongType",
                   scene,
                   kParticlesCsv,
                   {"{config}", "--set", "friction.mu0=abc"},
                   {"friction.mu0"}});
  cases.push_back({"UnknownOption", scene, kParticlesCsv, {"{config}", "--bogus"}, {"--bogus"}});
  cases.push_back(
      {"NonexistentConfigFile", scene, kParticlesCsv, {"{dir}/nothere.toml"}, {"nothere.toml"}});
  {
    const std::string c = scene + "[fluid\neta_f = 0.0\n";
    cases.push_back({"InvalidTomlSyntax",
                     c,
                     kParticlesCsv,
                     run_config,
                     {"scene.toml:" + std::to_string(line_of(c, "[fluid"))}});
  }
  cases.push_back({"NegativeSolverTolerance",
                   replaced(scene, "tolerance = 1e-10", "tolerance = -1e-6"),
                   kParticlesCsv,
                   run_config,
                   {"scene.toml", "solver.tolerance"}});
  cases.push_back(
      {"PeriodicAxisWithZeroBoxLength",
       replaced(scene, "trajectory_interval = 0.01\n",
                "trajectory_interval = 0.01\nbox = [0.0, 5.0, 5.0]\nperiodic = [true, false, "
                "false]\n"),
       kParticlesCsv,
       run_config,
       {"scene.toml", "scene.box"}});
  cases.push_back({"ZeroRunTimeInScene",
                   replaced(scene, "time = 0.05", "time = 0.0"),
                   kParticlesCsv,
                   run_config,
                   {"scene.toml", "run.time"}});
  cases.push_back({"CellTooSmallForItsSpheres",
                   "[cell]\nsize = [1.0, 1.0, 1.0]\n",
                   kParticlesCsv,
                   run_config,
                   {"cell.size", "4 largest radii"}});
  cases.push_back({"CellWithNoMobileSphere",
                   "[cell]\nsize = [4.0, 4.0, 4.5]\nphi = 0.05\n",
                   kParticlesCsv,
                   run_config,
                   {"scene.toml", "no mobile sphere"}});
  cases.push_back({"ResumeWithoutACheckpoint",
                   "[cell]\nsize = [8.0, 5.0, 9.0]\n",
                   kParticlesCsv,
                   {"{config}", "--resume"},
                   {"--resume", "checkpoint.bin"}});
  cases.push_back({"ResumeOfASceneWithoutACheckpoint",
                   scene,
                   kParticlesCsv,
                   {"{config}", "--resume"},
                   {"--resume", "checkpoint.bin"}});
  cases.push_back({"SedimentGivenToRun",
                   "[sediment]\n",
                   kParticlesCsv,
                   run_config,
                   {"scene.toml", "dilatant jam"}});
  return cases;
}

class CliBadInput : public ::testing::TestWithParam<BadInput> {};

TEST_P(CliBadInput, ExitsWithCode2AndOneLineNamingTheCulpritAndWritesNoResults) {
  const BadInput& c = GetParam();
  ASSERT_FALSE(c.config.empty()) << "test set-up: a replaced() pattern was not found";
  TempDir dir;
  const fs::path config = dir.write("scene.toml", c.config);
  dir.write("particles.csv", c.particles);
  const fs::path out = dir.path() / "out";

  std::vector<std::string> args = {"run"};
  for (const auto& a : c.args) {
    if (a == "{config}") {
      args.push_back(config.string());
    } else if (a.rfind("{dir}", 0) == 0) {
      args.push_back(dir.path().string() + a.substr(5));
    } else {
      args.push_back(a);
    }
  }
  args.insert(args.end(), {"--out", out.string()});
  const RunResult r = dir.run(args);

  EXPECT_EQ(r.exit_code, 2) << "stderr: " << r.err;
  ASSERT_FALSE(r.err.empty()) << "no message on stderr";
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << "stderr:\n" << r.err;
  EXPECT_EQ(r.err.back(), '\n') << "stderr: " << r.err;
  for (const auto& culprit : c.culprits) {
    EXPECT_NE(r.err.find(culprit), std::string::npos)
        << "the message does not name '" << culprit << "': " << r.err;
  }
  EXPECT_FALSE(fs::exists(out / "summary.json"));
  for (const auto& name : kResultFiles) {
    EXPECT_FALSE(fs::exists(out / name)) << name << " written despite bad input";
  }
  EXPECT_TRUE(part_files(out).empty());
}

INSTANTIATE_TEST_SUITE_P(Cli, CliBadInput, ::testing::ValuesIn(bad_inputs()),
                         [](const ::testing::TestParamInfo<BadInput>& p) { return p.param.name; });

// ---------------------------------------------------------------------------
// 4. Help.

TEST(Cli, HelpListsTheRunCommand) {
  TempDir dir;
  const RunResult r = dir.run({"--help"});
  EXPECT_EQ(r.exit_code, 0) << "stderr: " << r.err;
  EXPECT_NE(r.out.find("run"), std::string::npos) << r.out;
}

TEST(Cli, RunHelpDocumentsSet) {
  TempDir dir;
  const RunResult r = dir.run({"run", "--help"});
  EXPECT_EQ(r.exit_code, 0) << "stderr: " << r.err;
  EXPECT_NE(r.out.find("--set"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("--out"), std::string::npos) << r.out;
}

}  // namespace
}  // namespace dilatant::cli_test
