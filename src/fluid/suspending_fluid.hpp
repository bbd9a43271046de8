#pragma once
// The fluid a run is given: Stokes drag relative to an ambient shear flow
// and/or squeeze films between close surfaces, either one optional
// ([fluid] drag and lubrication; both off is the paper's literal model, in which
// the fluid acts only through the Stribeck friction of touching contacts).
#include <optional>

#include "fluid/fluid_forces.hpp"
#include "fluid/squeeze_film.hpp"
#include "fluid/stokes_drag.hpp"

namespace dilatant {

class SuspendingFluid final : public FluidForces {
 public:
  SuspendingFluid(std::optional<StokesDrag> drag, std::optional<SqueezeFilm> film)
      : drag_(drag), film_(film) {}

  bool empty() const { return !drag_ && !film_; }
  // The ambient flow the drag is taken relative to (default: at rest).
  void set_ambient(const ShearFlow& flow) { flow_ = flow; }
  const ShearFlow& ambient() const { return flow_; }

  void body_drag(const World& world, BodyDrag& drag) const override;
  double pair_range(const World& world) const override;
  void pair_resistance(std::vector<Contact>& contacts, double dt) const override;

 private:
  std::optional<StokesDrag> drag_;
  std::optional<SqueezeFilm> film_;
  ShearFlow flow_;
};

}  // namespace dilatant
