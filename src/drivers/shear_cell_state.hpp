#pragma once
// Everything a shear-cell run carries from step to step. A checkpoint is this
// state written byte for byte, so a resumed run continues exactly where the
// interrupted one stopped (same floating-point results).
#include <filesystem>
#include <memory>
#include <string>
#include <unordered_map>
#include <vector>

#include "boundary/drive.hpp"
#include "detection/contact.hpp"
#include "drivers/shear_cell_builder.hpp"
#include "drivers/strain_schedule.hpp"
#include "measure/cell_measurements.hpp"
#include "measure/jam_watch.hpp"
#include "world/world.hpp"

namespace dilatant {

struct ShearCellState {
  World world;
  // What shears the cell (boundary/drive.hpp): its rough walls or its
  // Lees–Edwards images. Never null in a cell; the walls' contact law is a run
  // setting, not part of the state.
  std::unique_ptr<Drive> drive;
  ShearCellGeometry geometry;
  double dt = 0.0;
  std::unordered_map<std::uint64_t, ContactMemory> contact_memory;

  long steps = 0;
  double strain = 0.0;
  CellSchedules schedules;               // rows, snapshots, checkpoints (their `next`)
  std::vector<double> snapshot_strains;  // strain of each ParaView snapshot written
  CellMeasurements measurements;
  JamWatch jam;

  // The speed that sets the shear: the top wall's, or the images' above.
  double drive_speed() const { return drive->speed(world); }
};

// Writes the state atomically; reads it back (throws on a corrupt file).
void save_checkpoint(const std::filesystem::path& file, const ShearCellState& state);
// The bytes save_checkpoint writes.
std::string checkpoint_bytes(const ShearCellState& state);
ShearCellState load_checkpoint(const std::filesystem::path& file);
// The same from a checkpoint's bytes; `file` names it in messages.
ShearCellState read_checkpoint(std::string bytes, const std::filesystem::path& file);
// Rewrites the checksum at the end of a checkpoint's bytes to match the rest:
// for the fuzzer, whose mutations must reach the reader's checks behind it.
void seal_checkpoint(std::string& bytes);

}  // namespace dilatant
