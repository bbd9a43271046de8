#pragma once
// The paper's drive (docs/model.md "The shear cell"; Fernandez et al. 2013):
// rough walls at z = 0 and z = Lz, the top one pulled along x by a constant
// force F = tau Lx Ly. Stress control: the top wall's speed V is what the
// flow lets it reach,
//
//     M dV/dt = F + sum_c (force of contact c on a top-wall sphere)_x ,
//
// solved within each step as the wall's own block of the Gauss–Seidel
// iteration (rough_walls.hpp), so the wall has nothing to do between steps.
// Its bodies are the walls' glued spheres, driven bodies owned by the bottom
// or the top wall (wall_owner.hpp); the mean flow is the no-slip profile
// between the walls' mean surfaces.
#include "boundary/drive.hpp"
#include "boundary/rough_walls.hpp"

namespace dilatant {

// Where the walls' mean surfaces are: the no-slip profile runs between them
// (drivers/shear_cell_builder.hpp measures them when it builds the walls).
struct WallGap {
  double wall_radius_mean = 0.0;  // r_w: the bottom surface is at z = r_w
  double gap_height = 0.0;        // Lz - 2 r_w
};

class WallDrive final : public Drive {
 public:
  WallDrive(RoughWalls walls, WallGap gap) : walls_(std::move(walls)), gap_(gap) {}

  // The top wall's drive force for `spec`, tau Lx Ly.
  static double drive_force(const DriveSpec& spec) {
    return spec.shear_stress * spec.size[0] * spec.size[1];
  }

  std::string_view name() const override { return "walls"; }
  std::string_view mover() const override { return "wall"; }

  Boundary* contact_block() override { return &walls_; }
  void set_contact_law(FrictionLaw law) override { walls_.set_contact_law(std::move(law)); }
  double time_step_bound(const World& world, double reach, double span) const override;
  double fed_work(const World&, double, double) const override { return walls_.drive_work(); }
  // Nothing: the wall answered the contacts within the step (its block).
  void respond(World&, const StepStress&, double) override {}

  double speed(const World&) const override { return walls_.top().velocity; }
  ShearFlow mean_flow(const World& world) const override;
  double kinetic_energy() const override { return walls_.kinetic_energy(); }

  bool bounded_by_walls() const override { return true; }
  WallForces wall_forces(const World& world, const std::vector<Contact>& contacts,
                         double dt) const override {
    return dilatant::wall_forces(world.bodies, contacts, dt);
  }
  double normal_stress(const World& world, const WallForces& f, double sigma_zz) const override;
  BulkRegion bulk_region(const World& world) const override;

  bool adopt(const DriveSpec& spec, World& world) override;
  DriveRecord record(const World& world) const override;

  const RoughWalls& walls() const { return walls_; }

 private:
  RoughWalls walls_;
  WallGap gap_;
};

}  // namespace dilatant
