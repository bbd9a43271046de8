#pragma once
// Walls that never move: bodies of infinite mass (glued spheres) whose contacts
// obey a law of their own, and no degree of freedom to solve. The packing
// growth (drivers/packing_growth.cpp) sees the shear cell's walls this way
// before the top wall is set free.
#include <utility>
#include <vector>

#include "boundary/boundary.hpp"

namespace dilatant {

class FixedWalls final : public Boundary {
 public:
  FixedWalls(std::vector<BodyGroup> group, FrictionLaw law)
      : group_(std::move(group)), law_(std::move(law)) {}

  std::span<const BodyGroup> body_groups() const override { return group_; }
  const FrictionLaw& contact_law() const override { return law_; }
  void predict(Bodies&, double) override {}
  void begin_solve(const std::vector<Contact>&) override {}
  void solve_block(const std::vector<Contact>&, Bodies&) override {}

 private:
  std::vector<BodyGroup> group_;
  FrictionLaw law_;
};

}  // namespace dilatant
