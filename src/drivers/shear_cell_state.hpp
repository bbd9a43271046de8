#pragma once
// Everything a shear-cell run carries from step to step. A checkpoint is this
// state written byte for byte, so a resumed run continues exactly where the
// interrupted one stopped (same floating-point results).
#include <filesystem>
#include <string>
#include <unordered_map>
#include <vector>

#include "boundary/lees_edwards.hpp"
#include "boundary/rough_walls.hpp"
#include "detection/contact.hpp"
#include "drivers/shear_cell_builder.hpp"
#include "measure/contact_statistics.hpp"
#include "measure/flow_series.hpp"
#include "measure/velocity_profile.hpp"
#include "world/world.hpp"

namespace dilatant {

struct ShearCellState {
  World world;
  // The cell's boundary: rough walls, or (world.box.lees_edwards) Lees–Edwards
  // images, whose speed V is world.box.shear_velocity. The other one is empty
  // (walls without bodies, a Lees–Edwards drive of zeros).
  RoughWalls walls;  // their contact law is a run setting, not part of the state
  LeesEdwards lees_edwards;
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

  bool is_lees_edwards() const { return world.box.lees_edwards; }
  Boundary& boundary() { return is_lees_edwards() ? static_cast<Boundary&>(lees_edwards) : walls; }
  // The speed that sets the shear: the top wall's, or the images' above.
  double boundary_velocity() const {
    return is_lees_edwards() ? world.box.shear_velocity : walls.top().velocity;
  }
};

// Writes the state atomically; reads it back (throws on a corrupt file).
void save_checkpoint(const std::filesystem::path& file, const ShearCellState& state);
ShearCellState load_checkpoint(const std::filesystem::path& file);
// The same from a checkpoint's bytes; `file` names it in messages.
ShearCellState read_checkpoint(std::string bytes, const std::filesystem::path& file);

}  // namespace dilatant
