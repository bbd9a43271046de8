// A sediment's checkpoint and resume (drivers/sediment_run.hpp): the samples
// a run finished are kept, a resumed run adds the rest and writes what an
// uninterrupted run writes; a stop abandons the running sample only; a
// checkpoint that does not belong to the run is refused as bad input naming
// its file. A tiny box (5 x 5 x 8 R) keeps each sample short.
#include "drivers/sediment_checkpoint.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "drivers/sediment_run.hpp"
#include "io/input_error.hpp"
#include "io/io_test_files.hpp"

namespace dilatant::sediment_checkpoint_test {
namespace {

namespace fs = std::filesystem;

class SedimentCheckpoint : public ::testing::Test {
 protected:
  fs::path at(const std::string& name) const { return dir_.path() / name; }
  static Config config(int samples, double mu0 = 1.0) {
    // 2 R excluded at floor and surface: the box's 8 R leave a slab to measure.
    return parse_config(
        "[sediment]\nsize = [5.0, 5.0, 8.0]\nexclusion = 2.0\n", "<test>", fs::current_path(),
        {"sediment.samples=" + std::to_string(samples), "friction.mu0=" + std::to_string(mu0)});
  }
  SedimentOutcome run(const std::string& out, const Config& c, bool resume = false,
                      const std::atomic<bool>* stop = nullptr) const {
    return run_sediment(c, SedimentRunOptions{RunOptions{at(out), true}, resume, stop});
  }
  std::string refusal(const std::string& out, const Config& c) const {
    try {
      run(out, c, /*resume=*/true);
    } catch (const InputError& e) {
      return e.what();
    }
    return "";
  }
  // summary.json up to its wall time (the last key but one of the run's).
  std::string summary(const std::string& out) const {
    const std::string s = test::read_text(at(out) / "summary.json");
    return s.substr(0, s.find("\"wall_time_s\""));
  }

  test::TempDir dir_;
};

TEST_F(SedimentCheckpoint, SamplesAddedOnResumeGiveTheUninterruptedRunsResults) {
  const SedimentOutcome whole = run("whole", config(2));
  run("grown", config(1));
  const SedimentOutcome grown = run("grown", config(2), /*resume=*/true);
  EXPECT_FALSE(grown.interrupted);
  EXPECT_EQ(grown.steps, whole.steps);
  EXPECT_GT(whole.phi_max, 0.5);  // a measured fraction, not an empty slab's 0
  EXPECT_EQ(grown.phi_max, whole.phi_max);
  EXPECT_EQ(test::read_text(dir_.path() / "grown" / "samples.csv"),
            test::read_text(dir_.path() / "whole" / "samples.csv"));
  EXPECT_EQ(summary("grown"), summary("whole"));
  EXPECT_EQ(load_sediment_checkpoint(dir_.path() / "grown" / "checkpoint.bin").size(), 2u);
}

TEST_F(SedimentCheckpoint, AStopAbandonsTheRunningSampleAndWritesNoSummary) {
  run("a", config(1));
  const std::atomic<bool> stop{true};
  const SedimentOutcome stopped = run("a", config(2), /*resume=*/true, &stop);
  EXPECT_TRUE(stopped.interrupted);
  EXPECT_FALSE(fs::exists(dir_.path() / "a" / "summary.json"));  // a finished run's, removed
  // The finished sample stays, in the checkpoint and the table.
  EXPECT_EQ(load_sediment_checkpoint(dir_.path() / "a" / "checkpoint.bin").size(), 1u);
  const std::string table = test::read_text(dir_.path() / "a" / "samples.csv");
  EXPECT_EQ(std::count(table.begin(), table.end(), '\n'), 2);  // header and one sample
}

TEST_F(SedimentCheckpoint, ARunOfAnotherConfigurationOrFewerSamplesIsNotResumed) {
  run("a", config(2));
  EXPECT_NE(refusal("a", config(2, 0.5)).find("another configuration"), std::string::npos);
  EXPECT_NE(refusal("a", config(1)).find("cannot remove any"), std::string::npos);
}

TEST_F(SedimentCheckpoint, ADamagedCheckpointIsRefusedNamingItsFile) {
  run("a", config(1));
  std::string bytes = test::read_text(dir_.path() / "a" / "checkpoint.bin");
  bytes[20] = static_cast<char>(bytes[20] ^ 0x01);
  std::ofstream(dir_.path() / "a" / "checkpoint.bin", std::ios::binary) << bytes;
  const std::string message = refusal("a", config(2));
  EXPECT_NE(message.find("checkpoint.bin: checkpoint is damaged or truncated"), std::string::npos)
      << message;
}

}  // namespace
}  // namespace dilatant::sediment_checkpoint_test
