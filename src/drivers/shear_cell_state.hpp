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
#include "measure/contact_statistics.hpp"
#include "measure/flow_series.hpp"
#include "measure/velocity_profile.hpp"
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
  double next_row_strain = 0.0;
  double next_snapshot_strain = 0.0;
  double next_checkpoint_strain = 0.0;
  std::vector<double> snapshot_strains;  // strain of each ParaView snapshot written
  IntervalSums interval;
  std::vector<FlowRow> rows;
  VelocityProfile profile;
  SommerfeldHistogram histogram;
  // Jam detection: strain and time at the start of the current window.
  double jam_window_strain = 0.0;
  double jam_window_time = 0.0;
  bool jammed = false;

  // The speed that sets the shear: the top wall's, or the images' above.
  double drive_speed() const { return drive->speed(world); }
};

// Writes the state atomically; reads it back (throws on a corrupt file).
void save_checkpoint(const std::filesystem::path& file, const ShearCellState& state);
ShearCellState load_checkpoint(const std::filesystem::path& file);
// The same from a checkpoint's bytes; `file` names it in messages.
ShearCellState read_checkpoint(std::string bytes, const std::filesystem::path& file);

}  // namespace dilatant
