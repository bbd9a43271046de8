#pragma once
// Walls that never move: driven bodies of infinite mass (glued spheres,
// world/bodies.hpp) whose contacts obey a law of their own, and no degree of
// freedom to solve. The packing growth (drivers/packing_growth.cpp) sees the
// shear cell's walls this way before the top wall is set free.
#include <utility>

#include "boundary/boundary.hpp"

namespace dilatant {

class FixedWalls final : public Boundary {
 public:
  explicit FixedWalls(FrictionLaw law) : law_(std::move(law)) {}

  const FrictionLaw& contact_law() const override { return law_; }
  void predict(Bodies&, double) override {}
  void begin_solve(const std::vector<Contact>&, const Bodies&) override {}
  void solve_block(const std::vector<Contact>&, Bodies&) override {}
  WallBlock* coupled_block() override { return nullptr; }
  void save_state() override {}  // nothing moves
  void restore_state() override {}

 private:
  FrictionLaw law_;
};

}  // namespace dilatant
