// Every committed fuzzing input, replayed through its reader in the ordinary
// builds (Release, and ASan + UBSan): the seeds of fuzz/corpus/TARGET/ and the
// crashers of fuzz/crashes/TARGET/ kept as regressions (scripts/fuzz.sh). A
// reader may accept or refuse each input; it must not crash, trip a sanitizer
// or throw anything but its refusal (fuzz/fuzz_targets.hpp).
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "drivers/scene_checkpoint.hpp"
#include "drivers/sediment_checkpoint.hpp"
#include "fuzz_targets.hpp"

namespace dilatant::corpus_replay_test {
namespace {

namespace fs = std::filesystem;

std::string bytes_of(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// Inputs under fuzz/corpus/ and fuzz/crashes/, each with its target's name.
std::vector<std::pair<std::string, fs::path>> committed_inputs() {
  std::vector<std::pair<std::string, fs::path>> out;
  for (const char* kind : {"corpus", "crashes"}) {
    const fs::path root = fs::path(DILATANT_SOURCE_DIR) / "fuzz" / kind;
    if (!fs::exists(root)) continue;
    for (const auto& folder : fs::directory_iterator(root)) {
      if (!folder.is_directory()) continue;
      for (const auto& file : fs::directory_iterator(folder.path()))
        if (file.is_regular_file())
          out.emplace_back(folder.path().filename().string(), file.path());
    }
  }
  return out;
}

TEST(FuzzCorpus, EveryCommittedInputIsAcceptedOrRefusedCleanly) {
  const auto inputs = committed_inputs();
  // The five readers have seeds (a missing folder would test nothing).
  for (const char* reader :
       {"config", "particles_csv", "checkpoint", "rheometer_file", "predict_tables"}) {
    EXPECT_TRUE(std::any_of(inputs.begin(), inputs.end(),
                            [&](const auto& input) { return input.first == reader; }))
        << "no committed input for " << reader;
  }
  for (const auto& [reader, file] : inputs) {
    const dilatant::fuzz::Target target = dilatant::fuzz::target_named(reader);
    ASSERT_NE(target, nullptr) << file << ": no fuzz target named " << reader;
    const std::string bytes = bytes_of(file);
    EXPECT_NO_THROW(target(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size()))
        << file;
  }
}

// The checkpoint target's seeds of the scene and sediment formats are whole
// checkpoints their own readers accept (a short `dilatant run` of the three
// spheres of SceneCheckpoint.*, a two-sample `dilatant jam` of the 5 x 5 x 8
// box): the fuzzer's mutations start from inside those readers, not at their
// magic. Re-made like the shear cell's seeds when a format changes
// (docs/reliability.md "Fuzzing").
TEST(FuzzCorpus, SceneAndSedimentSeedsAreWholeCheckpoints) {
  const fs::path seeds = fs::path(DILATANT_SOURCE_DIR) / "fuzz/corpus/checkpoint";
  const auto scene =
      read_scene_checkpoint(bytes_of(seeds / "scene-three-spheres.bin"), "scene-three-spheres.bin");
  EXPECT_EQ(scene.progress.position.size(), 3u);
  EXPECT_GT(scene.progress.time, 0.0);
  EXPECT_EQ(read_sediment_checkpoint(bytes_of(seeds / "sediment-two-samples.bin"),
                                     "sediment-two-samples.bin")
                .size(),
            2u);
}

// The harness itself: refusals are swallowed, the accepted seed returns.
TEST(FuzzCorpus, TheHarnessSwallowsRefusalsOnly) {
  const std::string not_toml = "[cell\nphi = ";
  EXPECT_NO_THROW(dilatant::fuzz::config(reinterpret_cast<const std::uint8_t*>(not_toml.data()),
                                         not_toml.size()));
  const std::string not_a_checkpoint = "DILATANT?";
  EXPECT_NO_THROW(dilatant::fuzz::checkpoint(
      reinterpret_cast<const std::uint8_t*>(not_a_checkpoint.data()), not_a_checkpoint.size()));
  EXPECT_EQ(dilatant::fuzz::target_named("no such reader"), nullptr);
}

}  // namespace
}  // namespace dilatant::corpus_replay_test
