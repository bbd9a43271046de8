// Checkpoints (drivers/shear_cell_state.hpp): read back exactly, and a file of
// another format is refused with a message that says what it is.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>
#include <vector>

#include "boundary/image_drive.hpp"
#include "drivers/shear_cell.hpp"

namespace dilatant::checkpoint_test {
namespace {

std::filesystem::path tiny_checkpoint(const std::string& name) {
  const auto file = std::filesystem::temp_directory_path() /
                    ("dilatant_checkpoint_" + name + "_" + std::to_string(::getpid()) + ".bin");
  ShearCell cell(default_cell_config(
      {"cell.size=[6.0, 5.0, 7.0]", "run.strain=0.01", "run.transient_strain=0"}));
  cell.step();
  cell.write_checkpoint(file);
  return file;
}

std::string message_of(const std::filesystem::path& file) {
  try {
    load_checkpoint(file);
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}

TEST(Checkpoint, ReadsBackTheStateItWrote) {
  const auto file = tiny_checkpoint("same");
  const ShearCellState s = load_checkpoint(file);
  EXPECT_EQ(s.steps, 1);
  EXPECT_GT(s.world.bodies.size(), 0u);
  // The bodies' owners come back from the drive's record, one a body.
  EXPECT_EQ(s.world.bodies.owner.size(), s.world.bodies.size());
  EXPECT_EQ(s.world.bodies.motion.size(), s.world.bodies.size());
  EXPECT_GT(std::count(s.world.bodies.motion.begin(), s.world.bodies.motion.end(), Motion::Driven),
            0);
  std::filesystem::remove(file);
}

TEST(Checkpoint, AnOlderFormatIsNamedAsSuch) {
  const auto file = tiny_checkpoint("old");
  {
    std::fstream f(file, std::ios::in | std::ios::out | std::ios::binary);
    f.seekp(7);
    f.put('6');  // "DILATNT6": the format before rows located their largest contact residual
  }
  EXPECT_NE(message_of(file).find("checkpoint of an older dilatant (format 6; this version reads "
                                  "format 9)"),
            std::string::npos)
      << message_of(file);
  {
    std::fstream f(file, std::ios::in | std::ios::out | std::ios::binary);
    f.seekp(0);
    f.put('X');
  }
  EXPECT_NE(message_of(file).find("not a dilatant checkpoint"), std::string::npos);
  std::filesystem::remove(file);
}

// Every byte is covered by the CRC-32 at the end (format 8): one bit changed
// anywhere after the magic, trailer included, is refused naming the file.
TEST(Checkpoint, AnyChangedBitIsRefused) {
  const auto file = tiny_checkpoint("bits");
  std::string bytes;
  {
    std::ifstream in(file, std::ios::binary);
    bytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  ASSERT_GT(bytes.size(), 100u);
  // 64 positions spread over the file after the 8-byte magic, and its last byte.
  std::vector<std::size_t> positions;
  for (std::size_t k = 0; k < 64; ++k) positions.push_back(8 + k * (bytes.size() - 9) / 63);
  for (const std::size_t at : positions) {
    std::string damaged = bytes;
    damaged[at] = static_cast<char>(damaged[at] ^ 0x10);
    try {
      (void)read_checkpoint(damaged, file);
      ADD_FAILURE() << "a changed bit at byte " << at << " of " << bytes.size() << " was read";
    } catch (const std::runtime_error& e) {
      const std::string what = e.what();
      EXPECT_EQ(what.rfind(file.string(), 0), 0u) << what;
      EXPECT_NE(what.find("damaged"), std::string::npos) << what;
    }
  }
  // Sealed again (the fuzzer's way), the same bytes read back.
  std::string resealed = bytes;
  seal_checkpoint(resealed);
  EXPECT_EQ(resealed, bytes);
  std::filesystem::remove(file);
}

// Format 9 added the Lees–Edwards pressure control after the images'
// control; a format-8 file (the committed fuzz seed, written by a short
// Lees–Edwards run) still reads, as a state without it.
TEST(Checkpoint, ReadsFormatEightAsAStateWithoutPressureControl) {
  const auto file = std::filesystem::path(DILATANT_SOURCE_DIR) / "fuzz" / "corpus" / "checkpoint" /
                    "small-lees-edwards.bin";
  std::string bytes;
  {
    std::ifstream in(file, std::ios::binary);
    bytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  ASSERT_EQ(bytes.substr(0, 8), "DILATNT8");
  const ShearCellState s = read_checkpoint(bytes, file);
  EXPECT_TRUE(s.world.box.lees_edwards);
  const auto* images = dynamic_cast<const ImageDrive*>(s.drive.get());
  ASSERT_NE(images, nullptr);
  EXPECT_FALSE(images->control().pressure_controlled);
  EXPECT_EQ(images->control().height_speed, 0.0);
}

// A pressure-controlled state comes back with its height and the lid's speed.
TEST(Checkpoint, KeepsTheHeightUnderPressureControl) {
  const auto file = std::filesystem::temp_directory_path() /
                    ("dilatant_checkpoint_pressure_" + std::to_string(::getpid()) + ".bin");
  ShearCell cell(
      default_cell_config({"cell.size=[6.0, 5.0, 7.0]", "run.strain=0.01", "run.transient_strain=0",
                           "cell.boundary=\"lees-edwards\"", "cell.control=\"pressure\"",
                           "cell.shear_rate=0.1", "cell.normal_stress=3.0"}));
  for (int n = 0; n < 3; ++n) cell.step();
  cell.write_checkpoint(file);
  const ShearCellState s = load_checkpoint(file);
  const auto& before = dynamic_cast<const ImageDrive&>(*cell.state().drive).control();
  const auto* images = dynamic_cast<const ImageDrive*>(s.drive.get());
  ASSERT_NE(images, nullptr);
  EXPECT_TRUE(images->control().pressure_controlled);
  EXPECT_NE(before.height_speed, 0.0);
  EXPECT_EQ(images->control().height_speed, before.height_speed);
  EXPECT_EQ(images->control().normal_force, 3.0 * 6.0 * 5.0);
  EXPECT_EQ(s.world.box.length, cell.state().world.box.length);
  EXPECT_NE(s.world.box.length[2], 7.0);
  std::filesystem::remove(file);
}

}  // namespace
}  // namespace dilatant::checkpoint_test
