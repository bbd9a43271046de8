#pragma once
// The moving wall of the shear cell: one rigid body made of glued spheres that
// moves along x only (its z is fixed: the cell keeps its volume), driven by a
// constant force. Its spheres are bodies of infinite mass in the contact
// problem; the wall's single degree of freedom is solved as its own block
// (solver/contact_solver.hpp) and copied to its spheres.
#include <cstdint>
#include <vector>

namespace dilatant {

struct SlidingWall {
  std::vector<std::int32_t> spheres;  // indices into Bodies
  double mass = 0.0;
  double drive_force = 0.0;  // along +x
  double velocity = 0.0;     // along x
};

}  // namespace dilatant
