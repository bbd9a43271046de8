#include "drivers/scene_checkpoint.hpp"

#include <fmt/format.h>

#include <cstring>
#include <stdexcept>
#include <utility>

#include "io/atomic_file.hpp"
#include "io/binary_archive.hpp"
#include "io/checksum.hpp"
#include "io/contact_memory_archive.hpp"
#include "io/input_error.hpp"
#include "io/text.hpp"

namespace dilatant {

namespace {

// "DILSCEN1"; a shear cell's checkpoints begin with "DILATNT"
// (drivers/shear_cell_state.cpp).
constexpr std::uint64_t kSceneMagic = 0x314e4543534c4944ULL;
constexpr std::uint64_t kCellMagicMask = 0x00ffffffffffffffULL;
constexpr std::uint64_t kCellMagic = 0x00544e54414c4944ULL;

// One function serves both directions so the field order cannot diverge;
// StepStatistics field by field (its padding would make the bytes vary).
template <class Archive, class Checkpoint>
void visit_scene(Archive& a, Checkpoint& c) {
  auto& p = c.progress;
  a.vector(p.position);
  a.vector(p.velocity);
  a.vector(p.angular_velocity);
  a.value(p.time);
  a.value(p.whole_steps);
  a.value(p.rest_of_step);
  auto& s = p.statistics;
  a.value(s.steps);
  a.value(s.unconverged);
  a.value(s.redone);
  a.value(s.iterations_total);
  a.value(s.iterations_max);
  a.value(s.residual_max);
  a.value(s.contact_residual_max);
  a.value(s.overlap_max);
  a.value(c.particles_crc);
  a.value(c.next_frame);
  a.value(c.timeseries_bytes);
  a.value(c.trajectory_bytes);
}

}  // namespace

std::string scene_checkpoint_bytes(const SceneCheckpoint& checkpoint) {
  BinaryWriter w;
  w.value(kSceneMagic);
  // visit_scene needs mutable access for the reader; the writer only reads.
  visit_scene(w, const_cast<SceneCheckpoint&>(checkpoint));
  write_contact_memory(w, checkpoint.progress.contact_memory);
  std::string bytes = w.release();
  append_crc_trailer(bytes);
  return bytes;
}

void save_scene_checkpoint(const std::filesystem::path& file, const SceneCheckpoint& checkpoint) {
  write_file_atomically(file, scene_checkpoint_bytes(checkpoint));
}

SceneCheckpoint load_scene_checkpoint(const std::filesystem::path& file) {
  return parse_checkpoint_file(
      file, [&](std::string bytes) { return read_scene_checkpoint(std::move(bytes), file); });
}

SceneCheckpoint read_scene_checkpoint(std::string bytes, const std::filesystem::path& file) {
  std::uint64_t magic = 0;
  if (bytes.size() < sizeof(magic)) throw std::runtime_error("checkpoint is truncated");
  std::memcpy(&magic, bytes.data(), sizeof(magic));
  if ((magic & kCellMagicMask) == kCellMagic)
    throw std::runtime_error(file.string() +
                             ": a shear cell's checkpoint, not a scene's: resume it with its "
                             "[cell] configuration");
  if (magic != kSceneMagic) throw std::runtime_error(file.string() + ": not a dilatant checkpoint");
  check_crc_trailer(bytes, sizeof(magic), file);
  BinaryReader r(std::move(bytes));
  r.end_before(kCrcTrailerBytes);
  r.value(magic);
  SceneCheckpoint c;
  visit_scene(r, c);
  c.progress.contact_memory = read_contact_memory(r, file);
  if (!r.at_end()) throw std::runtime_error(file.string() + ": checkpoint has trailing data");
  const SceneProgress& p = c.progress;
  if (p.velocity.size() != p.position.size() || p.angular_velocity.size() != p.position.size())
    throw std::runtime_error(file.string() + ": corrupt checkpoint (body arrays)");
  if (p.whole_steps < 0 || p.statistics.steps < 0 || !(p.rest_of_step >= 0.0))
    throw std::runtime_error(file.string() + ": corrupt checkpoint (step counts)");
  return c;
}

std::uint32_t scene_particles_crc(const Config& config) {
  return crc32_of(read_input_file(config.scene()->particles, "particles file"));
}

void restore_scene(Scene& scene, SceneCheckpoint checkpoint, const Config& config,
                   const std::filesystem::path& file) {
  if (checkpoint.particles_crc != scene_particles_crc(config))
    throw InputError(fmt::format(
        "{}: the particles file changed since the run of {} began (its CRC-32 differs): resume "
        "with the file it was built from, or run anew",
        config.scene()->particles.string(), file.string()));
  try {
    scene.restore(std::move(checkpoint.progress));
  } catch (const std::runtime_error& e) {
    throw InputError(fmt::format("{}: {}", file.string(), e.what()));
  }
}

}  // namespace dilatant
