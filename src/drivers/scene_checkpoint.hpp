#pragma once
// A scene's checkpoint, OUT/checkpoint.bin of `dilatant run` with a [scene]
// (drivers/scene_run.hpp): the scene's progress (drivers/scene.hpp), the
// CRC-32 of the particles file it was built from (a resume from another file
// is refused), when its next trajectory frame is due, and how many bytes of
// timeseries.csv and trajectory.csv it had written, so that a resumed run
// cuts off the rows written after the checkpoint (io/atomic_file.hpp). The
// file ends with the CRC-32 of every byte before it, as a shear cell's does
// (io/checksum.hpp).
#include <cstdint>
#include <filesystem>
#include <string>

#include "drivers/scene.hpp"

namespace dilatant {

struct SceneCheckpoint {
  SceneProgress progress;
  std::uint32_t particles_crc = 0;
  double next_frame = 0.0;  // time of the next trajectory frame
  std::uint64_t timeseries_bytes = 0, trajectory_bytes = 0;
};

// Written atomically (io/atomic_file.hpp).
void save_scene_checkpoint(const std::filesystem::path& file, const SceneCheckpoint& checkpoint);
std::string scene_checkpoint_bytes(const SceneCheckpoint& checkpoint);
// Throw InputError naming `file` for a missing, damaged or foreign
// file (a shear cell's checkpoint is named as such).
SceneCheckpoint load_scene_checkpoint(const std::filesystem::path& file);
SceneCheckpoint read_scene_checkpoint(std::string bytes, const std::filesystem::path& file);

// The CRC-32 of the particles file a scene of `config` is built from.
std::uint32_t scene_particles_crc(const Config& config);
// Puts `scene` (built from `config`) where the checkpoint in `file` left it.
// Throws InputError naming the particles file when it is not the one the
// checkpointed run was built from (its CRC-32), and naming `file` when the
// checkpoint holds another number of bodies.
void restore_scene(Scene& scene, SceneCheckpoint checkpoint, const Config& config,
                   const std::filesystem::path& file);

}  // namespace dilatant
