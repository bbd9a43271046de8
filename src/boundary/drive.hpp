#pragma once
// What shears a cell: the drive (docs/shear-cell.md). The shear cell
// (drivers/shear_cell.hpp) holds one and asks it, never what kind it is:
//
//   the step         its block in the contact problem (boundary.hpp; none if
//                    it takes no part), its bound on the time step, the work
//                    it fed into the flow over the step, and between steps its
//                    response to the measured stress;
//   its motion       its speed V and the shear rate V / Lz it imposes; the
//                    mean flow the fluid's drag and the kinetic stress are
//                    taken relative to; its own kinetic energy;
//   measurement      the forces on its walls, the normal stress it measures,
//                    the bulk region over which the cell measures;
//   continuation     taking over another run's control (a flow curve's next
//                    point), and its record in a checkpoint (drive_record.hpp).
//
// Two drives:
//
//   WallDrive   (wall_drive.hpp)   rough walls, the top one pulled by a constant
//                                  force: stress control (the paper's cell);
//   ImageDrive  (image_drive.hpp)  Lees–Edwards images, no walls: stress or
//                                  rate control, or rate and pressure control
//                                  (the box height follows the normal stress).
//
// An abstract class owned through std::unique_ptr rather than a std::variant:
// the cell calls its drive a few times per step, never inside the contact
// sweep, so a virtual call costs nothing measurable, and a third drive (an
// oscillating wall, a box whose height follows an imposed pressure) is one new
// class here that no cell code and no visitor has to list. The stepper's seam
// (Boundary) is virtual for the same reason.
//
// The drive acts on a World it does not own (the cell's state moves, the
// world with it): every call that reads or changes the world's motion is
// given it. The images' speed lives in the world's PeriodicBox, the one place
// detection and the contacts' relative velocity read it from.
#include <string_view>
#include <vector>

#include "boundary/boundary.hpp"
#include "boundary/wall_forces.hpp"
#include "detection/contact.hpp"
#include "friction/friction_law.hpp"
#include "geometry/vec3.hpp"
#include "world/shear_flow.hpp"
#include "world/world.hpp"

namespace dilatant {

struct DriveRecord;

// What a run's configuration asks of its drive ([cell]; drivers/ fills it).
enum class DriveKind { Walls, Images };
struct DriveSpec {
  DriveKind kind = DriveKind::Walls;
  bool rate_controlled = false;      // also under pressure control
  bool pressure_controlled = false;  // the box height follows normal_stress
  double shear_stress = 0.0;         // tau imposed (stress control), code units
  double shear_rate = 0.0;           // gamma_dot imposed (rate or pressure control)
  double normal_stress = 0.0;        // P = -sigma_zz imposed (pressure control)
  double mass = 0.0;                 // the driven mass M; 0: the drive's default
  Vec3 size = Vec3::Zero();          // Lx, Ly, Lz
};

// Where the cell measures its bulk. With walls: the central half of the gap,
// free of the layering at the walls, and the flow beyond one particle
// diameter of them. Without walls the flow is homogeneous and the whole box
// is bulk; its volume fraction is then the box's, exactly (a slab would cut
// the spheres that straddle the periodic boundary).
struct BulkRegion {
  double z_lo = 0.0, z_hi = 0.0;        // phi_bulk and the bulk shear rate
  double flow_lo = 0.0, flow_hi = 0.0;  // where the velocity profile should be linear
  bool whole_box = false;
};

// The particle stress of a step (measure/particle_stress.hpp), the parts a
// drive responds to: sigma_zx across the shear planes, sigma_zz normal to them
// (tensile positive: a compressed packing has sigma_zz < 0).
struct StepStress {
  double sigma_zx = 0.0;
  double sigma_zz = 0.0;
  // -d(-sigma_zz)/dW, the squeeze films' resistance to the pressure-controlled
  // box's lid (boundary/lid_resistance.hpp); 0 without films.
  double lid_resistance = 0.0;
};

class Drive {
 public:
  virtual ~Drive() = default;

  // As cell.boundary names it ("walls", "lees-edwards"), and what moves at
  // speed() ("wall", "boundary"): words for summary.json and messages.
  virtual std::string_view name() const = 0;
  virtual std::string_view mover() const = 0;

  // ---- the step ----
  // The drive's block in the contact problem, handed to the stepper; null if
  // it takes no part in it (its speed is constant within a step).
  virtual Boundary* contact_block() = 0;
  // The law of contacts that touch the drive's bodies (its driven bodies,
  // world/bodies.hpp, which measurements of the flow leave out): a run setting, not
  // part of the state (ignored by a drive without bodies).
  virtual void set_contact_law(FrictionLaw law) = 0;
  // The longest step in which the drive moves nothing by more than `reach`
  // relative to what lies `span` below it (drivers/cell_time_step.cpp, the
  // automatic step): span = the box height bounds the move in the lab frame,
  // span ~ R the move relative to a neighbour in the drive's mean flow.
  virtual double time_step_bound(const World& world, double reach, double span) const = 0;
  // The work the drive fed into the flow over the step just taken, of length
  // dt, whose measured particle shear stress was sigma_zx: the fed power
  // times dt.
  virtual double fed_work(const World& world, double sigma_zx, double dt) const = 0;
  // After that step: the drive's response to the measured stress, for the next.
  virtual void respond(World& world, const StepStress& stress, double dt) = 0;

  // ---- its motion ----
  // V: the top wall's speed, or the images' above the box.
  virtual double speed(const World& world) const = 0;
  // The shear rate it imposes, gamma_dot = V / Lz (the paper's definition).
  double shear_rate(const World& world) const { return speed(world) / world.box.length[2]; }
  // The mean flow of the cell (world/shear_flow.hpp).
  virtual ShearFlow mean_flow(const World& world) const = 0;
  // Kinetic energy of the drive's own degrees of freedom, beyond the bodies'.
  virtual double kinetic_energy() const = 0;

  // ---- what the cell measures ----
  // Whether walls bound the cell in z: their forces, their radius and the
  // fraction between them are measured (summary.json reports them as null
  // without walls).
  virtual bool bounded_by_walls() const = 0;
  // The forces of the step's contacts on the walls (zero without walls).
  virtual WallForces wall_forces(const World& world, const std::vector<Contact>& contacts,
                                 double dt) const = 0;
  // The normal stress the drive measures, compressive > 0: on its walls, from
  // their forces f; without walls the bulk's, -sigma_zz.
  virtual double normal_stress(const World& world, const WallForces& f, double sigma_zz) const = 0;
  virtual BulkRegion bulk_region(const World& world) const = 0;

  // ---- continuation and checkpoints ----
  // Takes over the control `spec` asks for (a flow curve's next point starts
  // from this drive's state); false, changing nothing, if the spec asks for
  // another drive or a cell this state cannot be.
  virtual bool adopt(const DriveSpec& spec, World& world) = 0;
  // What a checkpoint keeps of the drive driving `world` (drive_record.hpp).
  virtual DriveRecord record(const World& world) const = 0;
};

}  // namespace dilatant
