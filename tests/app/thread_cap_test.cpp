// More solver threads than the machine has hardware threads (issue: on 2 cores
// solver.threads = 4 / 16 / 1,024 took 31 / 21 / > 60 s where one thread took
// 0.3 s, silently): the engine uses at most the hardware threads
// (drivers/model_setup.hpp make_solver_settings()), and the run says so in one
// line, with the same results as a run that asked for that many.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <string>

#include "app/cli_runner.hpp"
#include "drivers/model_setup.hpp"

namespace dilatant::test::thread_cap_test {
namespace {

namespace fs = std::filesystem;

TEST(ThreadCap, TheSolverUsesAtMostTheHardwareThreads) {
  const int cores = hardware_threads();
  SolverConfig solver;
  for (const int asked : {cores + 1, 16 * cores, 1024}) {
    solver.threads = asked;
    EXPECT_EQ(make_solver_settings(solver).threads, cores) << asked;
    const std::string warning = thread_cap_warning(solver);
    EXPECT_NE(warning.find("solver.threads = " + std::to_string(asked)), std::string::npos)
        << warning;
    EXPECT_EQ(warning.find('\n'), std::string::npos);  // one line
  }
  solver.threads = 0;  // all of them
  EXPECT_EQ(make_solver_settings(solver).threads, cores);
  EXPECT_TRUE(thread_cap_warning(solver).empty());
  solver.threads = 1;
  EXPECT_EQ(make_solver_settings(solver).threads, 1);
  EXPECT_TRUE(thread_cap_warning(solver).empty());
}

TEST(ThreadCap, ARunAskingForTooManyThreadsWarnsOnceAndMatchesTheCappedRun) {
  CliDir dir;
  const auto run = [&](const std::string& threads, const fs::path& out) {
    return dir.run({"run", "--out", out.string(), "--set", "cell.size=[6.0, 5.0, 7.0]", "--set",
                    "run.strain=0.01", "--set", "run.transient_strain=0.005", "--set",
                    "run.snapshot_interval=0", "--set", "solver.threads=" + threads, "--quiet"});
  };
  const RunResult many = run("1024", dir.path() / "many");
  ASSERT_EQ(many.exit_code, 0) << many.err;
  EXPECT_NE(many.err.find("warning: solver.threads = 1024 is more than"), std::string::npos)
      << many.err;
  const RunResult capped = run(std::to_string(hardware_threads()), dir.path() / "capped");
  ASSERT_EQ(capped.exit_code, 0) << capped.err;
  EXPECT_EQ(capped.err.find("solver.threads"), std::string::npos) << capped.err;
  EXPECT_EQ(read_text(dir.path() / "many" / "timeseries.csv"),
            read_text(dir.path() / "capped" / "timeseries.csv"));
}

// A sweep's points side by side share the cores: jobs x solver threads above
// the hardware threads is said in one line (sweep_command.cpp).
TEST(ThreadCap, ASweepAskingForMoreThreadsThanCoresWarns) {
  const int cores = hardware_threads();
  EXPECT_TRUE(oversubscription_warning(1, cores).empty());
  EXPECT_TRUE(oversubscription_warning(cores, 1).empty());
  const std::string w = oversubscription_warning(cores + 1, 1);
  EXPECT_NE(w.find(fmt::format("ask for {} threads on this machine's {}", cores + 1, cores)),
            std::string::npos)
      << w;
  EXPECT_FALSE(oversubscription_warning(2, cores).empty());
}

}  // namespace
}  // namespace dilatant::test::thread_cap_test
