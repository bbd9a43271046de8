// A run whose solver stops at solver.max_iterations is never silent about it
// (docs/reliability.md): the CLI warns with the count of such steps and names
// the step and the two bodies of the largest contact residual; summary.json
// holds the same (contact_residual_max_step, contact_residual_max_bodies).
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "app/cli_runner.hpp"

namespace dilatant::test::unconverged_run_test {
namespace {

namespace fs = std::filesystem;

RunResult run_cell(const CliDir& dir, const fs::path& out, const std::string& max_iterations,
                   const std::string& redo = "false") {
  return dir.run({"run", "--out", out.string(), "--set", "cell.size=[6.0, 5.0, 7.0]", "--set",
                  "run.strain=0.02", "--set", "run.transient_strain=0.01", "--set",
                  "run.snapshot_interval=0", "--set", "solver.threads=1", "--set",
                  "solver.max_iterations=" + max_iterations, "--set",
                  "solver.redo_unconverged=" + redo, "--quiet"});
}

TEST(UnconvergedRun, NamesTheStepAndTheContactOfTheLargestResidual) {
  CliDir dir;
  const fs::path out = dir.path() / "out";
  // Three sweeps cannot solve a packing's contact network.
  const RunResult r = run_cell(dir, out, "3");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json summary = nlohmann::json::parse(read_text(out / "summary.json"));
  const long steps = summary["steps"].get<long>();
  ASSERT_GT(summary["frac_steps_unconverged"].get<double>(), 0.0);
  const long step = summary["contact_residual_max_step"].get<long>();
  EXPECT_GE(step, 0);
  EXPECT_LE(step, steps);
  ASSERT_EQ(summary["contact_residual_max_bodies"].size(), 2u);
  const long i = summary["contact_residual_max_bodies"][0].get<long>();
  const long j = summary["contact_residual_max_bodies"][1].get<long>();
  EXPECT_GE(i, 0);
  EXPECT_NE(i, j);
  EXPECT_GT(summary["contact_residual_max"].get<double>(), 1e-2);  // above solver.tolerance

  // The warning: how many steps, then where the worst was, as the summary says.
  EXPECT_NE(r.err.find("did not converge within solver.max_iterations = 3"), std::string::npos)
      << r.err;
  // "... was at step S between body I and (body|plane) J ..." (no std::regex:
  // GCC 12 warns inside its <regex> under the sanitizers).
  const std::string lead = "the largest contact residual, ";
  const auto at = r.err.find(lead);
  ASSERT_NE(at, std::string::npos) << r.err;
  const auto step_at = r.err.find(" was at step ", at);
  ASSERT_NE(step_at, std::string::npos) << r.err;
  std::istringstream where(r.err.substr(step_at + std::string(" was at step ").size()));
  long w_step = -1, w_i = -1, w_j = 0;
  std::string between, body, and_word, kind;
  where >> w_step >> between >> body >> w_i >> and_word >> kind >> w_j;
  ASSERT_FALSE(where.fail()) << r.err;
  EXPECT_EQ(between + body + and_word, "betweenbodyand") << r.err;
  EXPECT_EQ(w_step, step);
  EXPECT_EQ(w_i, i);
  ASSERT_TRUE(kind == "body" || kind == "plane") << r.err;
  EXPECT_EQ(w_j, kind == "plane" ? -j - 1 : j);

  // A converged run says nothing, and its summary still locates its (small) worst.
  const fs::path converged = dir.path() / "converged";
  const RunResult c = run_cell(dir, converged, "10000");
  ASSERT_EQ(c.exit_code, 0) << c.err;
  EXPECT_EQ(c.err.find("contact residual"), std::string::npos) << c.err;
  const nlohmann::json quiet = nlohmann::json::parse(read_text(converged / "summary.json"));
  EXPECT_EQ(quiet["frac_steps_unconverged"].get<double>(), 0.0);
  EXPECT_GE(quiet["contact_residual_max_step"].get<long>(), 0);
}

// With solver.redo_unconverged a step that three sweeps cannot solve is redone
// at dt/2, ..., dt/64 (solver/time_stepper.hpp) and then stops the run: exit 1,
// one line naming the step, the halvings and the two bodies, no summary.
TEST(UnconvergedRun, WithRedoAStepThatNeverConvergesStopsTheRunNamingIt) {
  CliDir dir;
  const fs::path out = dir.path() / "out";
  const RunResult r = run_cell(dir, out, "3", "true");
  ASSERT_EQ(r.exit_code, 1) << r.err;
  EXPECT_NE(r.err.find("step 1 (strain 0): the contact solve did not converge"), std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("(6 halvings)"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("worst at the contact of body id"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out / "summary.json"));

  // Enough sweeps: every step is accepted converged, none silently.
  const fs::path converged = dir.path() / "converged";
  const RunResult c = run_cell(dir, converged, "10000", "true");
  ASSERT_EQ(c.exit_code, 0) << c.err;
  const nlohmann::json summary = nlohmann::json::parse(read_text(converged / "summary.json"));
  EXPECT_EQ(summary["frac_steps_unconverged"].get<double>(), 0.0);
  EXPECT_LE(summary["contact_residual_max"].get<double>(), 1e-2);  // solver.tolerance
}

}  // namespace
}  // namespace dilatant::test::unconverged_run_test
