// Fault injection (issue 19, item 1): a sweep killed with SIGKILL at random
// moments, at least 20 times, and resumed each time, ends with the same
// flowcurves.csv as a sweep that was never interrupted. SIGKILL gives the
// program no chance to react: what survives is what the atomic writes
// (io/atomic_file.hpp) and the checkpoints left on disk.
#include <gtest/gtest.h>
#include <signal.h>

#include <chrono>
#include <fstream>
#include <iostream>
#include <random>
#include <thread>

#include "sweep/child_sweep.hpp"
#include "sweep/tiny_sweep.hpp"

namespace dilatant::sweep_kill_test {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

// `dilatant sweep FILE --out OUT` as a child process, stdout/stderr to /dev/null.
pid_t start_sweep(const fs::path& file, const fs::path& out) {
  return test::start_child({DILATANT_EXECUTABLE, "sweep", file.string(), "--out", out.string(),
                            "--jobs", "2", "--no-plots", "-q"});
}

using test::done_points;
using test::table_without_timing;
using test::wait_for;

TEST(SweepKill, TwentySigkillsAndResumesGiveTheUninterruptedTable) {
  test::TempDir dir;
  // The tiny grid, sheared longer and checkpointed often, so that kills land
  // in every phase: packing, running between checkpoints, writing files.
  std::string text = test::kTinyGrid;
  const auto run_at = text.find("[run]"), friction_at = text.find("[friction]");
  text = text.substr(0, run_at) +
         "[run]\nstrain = 2.0\ntransient_strain = 0.1\ncheckpoint_interval = 0.05\n"
         "snapshot_interval = 0.0\n\n" +
         text.substr(friction_at);
  const fs::path file = dir.path() / "kill.toml";
  std::ofstream(file) << text;

  const auto begin = Clock::now();
  ASSERT_EQ(wait_for(start_sweep(file, dir.path() / "straight")), 0);
  const double straight = std::chrono::duration<double>(Clock::now() - begin).count();

  // The first ten kills, and the even ones after, land after a random 3-9%
  // of the uninterrupted duration (packing, running between checkpoints,
  // writing files). The odd kills after the tenth first wait until the table
  // shows a finished point, then land within a random 0-5%: those are the
  // kills between points, placed by the sweep's own progress rather than by
  // the clock, so a slow or loaded machine (the sanitizer build beside other
  // tests) cannot push them all before the first point ends. Should the
  // sweep finish before its 20th kill, it starts over from an empty folder
  // with the delays halved: the 20 kills all land in one sweep.
  std::mt19937 random(19);
  double scale = 1.0;
  int kills = 0, attempts = 0;
  int kills_between_points = 0;  // with some points done and some not
  const fs::path killed = dir.path() / "killed";
  const fs::path table = killed / "flowcurves.csv";
  while (kills < 20 && attempts < 400) {
    ++attempts;
    const bool after_a_point = kills >= 10 && kills % 2 == 1;
    std::uniform_real_distribution<double> fraction(after_a_point ? 0.0 : 0.03 * scale,
                                                    (after_a_point ? 0.05 : 0.09) * scale);
    const pid_t pid = start_sweep(file, killed);
    bool exited = false;
    int code = 0;
    if (after_a_point)
      while (done_points(table) == 0) {
        if (waitpid(pid, &code, WNOHANG) == pid) {
          exited = true;
          break;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
      }
    if (!exited) {
      std::this_thread::sleep_for(std::chrono::duration<double>(fraction(random) * straight));
      kill(pid, SIGKILL);
      code = wait_for(pid);
    } else {
      code = WIFEXITED(code) ? WEXITSTATUS(code) : -WTERMSIG(code);
    }
    if (code == -SIGKILL) {
      ++kills;
      const std::size_t done = done_points(table);
      if (done > 0 && done < 4) ++kills_between_points;
      continue;
    }
    ASSERT_EQ(code, 0) << "a resumed sweep failed";
    fs::remove_all(killed);
    kills = 0;
    kills_between_points = 0;
    scale /= 2.0;
  }
  ASSERT_EQ(kills, 20);
  // The kills spread over the sweep, not all before its first point ended.
  EXPECT_GE(kills_between_points, 2);
  std::cout << "kills " << kills << " (" << kills_between_points << " between points), attempts "
            << attempts << ", uninterrupted " << straight << " s\n";
  ASSERT_EQ(wait_for(start_sweep(file, killed)), 0);
  EXPECT_EQ(table_without_timing(table),
            table_without_timing(dir.path() / "straight" / "flowcurves.csv"));
}

}  // namespace
}  // namespace dilatant::sweep_kill_test
