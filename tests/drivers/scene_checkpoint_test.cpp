// A scene's checkpoint and resume (drivers/scene_run.hpp): a run stopped and
// resumed, or finished and extended, writes the bytes an uninterrupted run
// writes; rows written after the checkpoint are cut off; a checkpoint that
// does not belong to the run (another configuration, another particles file,
// a damaged or foreign file) is refused as bad input naming its file.
#include "drivers/scene_checkpoint.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "drivers/scene_run.hpp"
#include "drivers/shear_cell.hpp"
#include "io/input_error.hpp"
#include "io/io_test_files.hpp"

namespace dilatant::scene_checkpoint_test {
namespace {

namespace fs = std::filesystem;

// Three spheres dropped on a floor, one thrown sideways into another, so that
// contacts open and close and the warm start matters across the checkpoint.
constexpr const char* kSceneToml = R"([scene]
particles = "particles.csv"
gravity = [0.0, 0.0, -9.81]
trajectory_interval = 0.01

[[scene.planes]]
point = [0.0, 0.0, 0.0]
normal = [0.0, 0.0, 1.0]

[friction]
law = "coulomb"
mu0 = 0.3

[solver]
dt = 1e-3

[run]
time = 0.1
)";

constexpr const char* kParticlesCsv =
    "id,x,y,z,r,vx\n"
    "0,0.0,0.0,0.6,0.5,0.0\n"
    "1,1.5,0.0,0.7,0.5,-2.0\n"
    "2,0.2,0.1,1.8,0.5,0.0\n";

class SceneCheckpoint : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_.write("scene.toml", kSceneToml);
    dir_.write("particles.csv", kParticlesCsv);
  }
  fs::path at(const std::string& name) const { return dir_.path() / name; }
  Config config(std::vector<std::string> overrides = {}) const {
    return load_config(at("scene.toml"), overrides);
  }
  SceneOutcome run(const std::string& out, const Config& c, bool resume = false,
                   const std::atomic<bool>* stop = nullptr) const {
    return run_scene(c, SceneRunOptions{RunOptions{at(out), true}, resume, stop});
  }
  // The files of two runs agree byte for byte (summary.json but its wall time).
  void expect_same_results(const std::string& a, const std::string& b) const {
    for (const char* f : {"trajectory.csv", "timeseries.csv", "contacts.csv"})
      EXPECT_EQ(test::read_text(at(a) / f), test::read_text(at(b) / f)) << f;
    const auto summary = [&](const std::string& run) {
      std::string s = test::read_text(at(run) / "summary.json");
      const auto end = s.find("\"wall_time_s\"");
      return end == std::string::npos ? s : s.substr(0, end);
    };
    EXPECT_EQ(summary(a), summary(b));
  }
  std::string refusal(const std::string& out, const Config& c) const {
    try {
      run(out, c, /*resume=*/true);
    } catch (const InputError& e) {
      return e.what();
    }
    return "";
  }

  test::TempDir dir_;
};

TEST_F(SceneCheckpoint, AStoppedRunResumedWritesTheUninterruptedRunsFiles) {
  run("whole", config());
  const std::atomic<bool> stop{true};  // stops after its first step
  const SceneOutcome stopped = run("stopped", config(), false, &stop);
  EXPECT_TRUE(stopped.interrupted);
  EXPECT_EQ(stopped.steps, 1);
  // Stopped: the series stay .part files for the resume, nothing published.
  EXPECT_TRUE(fs::exists(dir_.path() / "stopped" / "trajectory.csv.part"));
  EXPECT_FALSE(fs::exists(dir_.path() / "stopped" / "trajectory.csv"));
  EXPECT_FALSE(fs::exists(dir_.path() / "stopped" / "summary.json"));
  const SceneOutcome resumed = run("stopped", config(), /*resume=*/true);
  EXPECT_FALSE(resumed.interrupted);
  EXPECT_EQ(resumed.steps, 100);
  expect_same_results("whole", "stopped");
}

TEST_F(SceneCheckpoint, RowsWrittenAfterTheCheckpointAreCutOff) {
  // A run killed between checkpoints leaves rows its checkpoint does not know.
  run("whole", config());
  const std::atomic<bool> stop{true};
  run("killed", config(), false, &stop);
  for (const char* f : {"trajectory.csv.part", "timeseries.csv.part"})
    std::ofstream(dir_.path() / "killed" / f, std::ios::app) << "9,9,9,half a row";
  run("killed", config(), /*resume=*/true);
  expect_same_results("whole", "killed");
}

TEST_F(SceneCheckpoint, AFinishedRunResumedWithALongerTimeRunsOnAsOneRun) {
  run("long", config({"run.time=0.2"}));
  run("extended", config());
  const SceneOutcome again = run("extended", config(), /*resume=*/true);  // nothing left
  EXPECT_EQ(again.steps, 100);
  const SceneOutcome extended = run("extended", config({"run.time=0.2"}), /*resume=*/true);
  EXPECT_EQ(extended.steps, 200);
  expect_same_results("long", "extended");
}

TEST_F(SceneCheckpoint, ARunOfAnotherConfigurationIsNotResumed) {
  run("a", config());
  EXPECT_NE(refusal("a", config({"friction.mu0=0.5"})).find("another configuration"),
            std::string::npos);
  EXPECT_NE(refusal("a", config({"run.time=0.05"})).find("cannot shorten"), std::string::npos);
}

TEST_F(SceneCheckpoint, AChangedParticlesFileIsNamed) {
  run("a", config());
  dir_.write("particles.csv", std::string(kParticlesCsv) + "3,3.0,0.0,0.6,0.5,0.0\n");
  const std::string message = refusal("a", config());
  EXPECT_NE(message.find("particles.csv: the particles file changed"), std::string::npos)
      << message;
}

TEST_F(SceneCheckpoint, ADamagedCheckpointIsRefusedNamingItsFile) {
  run("a", config());
  std::string bytes = test::read_text(at("a") / "checkpoint.bin");
  bytes[40] = static_cast<char>(bytes[40] ^ 0x10);
  dir_.write("a/checkpoint.bin", bytes);
  const std::string message = refusal("a", config());
  EXPECT_NE(message.find("checkpoint.bin: checkpoint is damaged or truncated"), std::string::npos)
      << message;
}

TEST_F(SceneCheckpoint, AShearCellsCheckpointIsNamedAsSuch) {
  ShearCell cell(default_cell_config(
      {"cell.size=[6.0, 5.0, 7.0]", "run.strain=0.01", "run.transient_strain=0"}));
  cell.step();
  cell.write_checkpoint(dir_.path() / "cell.bin");
  try {
    load_scene_checkpoint(dir_.path() / "cell.bin");
    ADD_FAILURE() << "a shear cell's checkpoint was read as a scene's";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("a shear cell's checkpoint, not a scene's"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace dilatant::scene_checkpoint_test
