#pragma once
// Simulated centrifugation (the paper's measure of phi_max_BL, its Fig. 3a):
// a random suspension in a box periodic in x and y settles under strong gravity
// onto a flat floor, its contacts in boundary lubrication (Coulomb friction
// mu0), until it stops; the sediment's bulk fraction is the jamming fraction
// of that friction (measure/sediment_fraction.hpp).
//
// Units: the largest radius R = 1, the particle density rho_p = 1 and gravity
// g = 1, so times are in sqrt(R/g). With hard spheres and no Brownian motion
// the strength of the centrifuge does not enter on its own: only the Stokes
// number St = g tau^2 / R of the settling does, with tau = 2 rho_p R^2 /
// (9 eta_f) the viscous relaxation time of a sphere of radius R (its terminal
// speed is v_t = g tau). The fluid acts through Stokes drag on each sphere
// relative to a fluid at rest (fluid/stokes_drag.hpp): the dissipation that
// lets the sediment stop. Small St is the overdamped settling of fine powders.
//
//     Sediment s(settings);
//     while (!s.settled() && !s.timed_out()) s.step();
//     SedimentFraction f = s.measure(4.0);
#include <cstdint>
#include <memory>

#include "fluid/suspending_fluid.hpp"
#include "measure/sediment_fraction.hpp"
#include "solver/time_stepper.hpp"
#include "world/world.hpp"

namespace dilatant {

struct SedimentSettings {
  double lx = 12.0, ly = 12.0;  // periodic box, R
  double height = 40.0;         // floor (z = 0) to lid, R
  double phi_initial = 0.47;    // of the suspension filling floor to lid (the paper's 0.47)
  double radius_min = 0.8, radius_max = 1.0;
  std::int64_t seed = 1;
  double mu0 = 0.0;             // Coulomb friction, sphere-sphere and sphere-floor
  double stokes_number = 1e-3;  // g tau^2 / R
  SolverSettings solver{.tolerance = 1e-4};
  double dt = 0.0;                // 0: automatic (2% of radius_min at the terminal speed)
  double max_time_factor = 20.0;  // give up after this many height / v_t
};

class Sediment {
 public:
  // Throws std::runtime_error if the initial suspension cannot be packed.
  explicit Sediment(const SedimentSettings& settings);

  const StepReport& step();
  // Settled: over the last window of kSettleWindow R / v_t, the spheres' mean
  // height changed by less than kSettleHeight R (a free sphere falls
  // kSettleWindow R in that time).
  bool settled() const { return settled_; }
  bool timed_out() const { return world_.time >= max_time_; }

  SedimentFraction measure(double exclusion) const {
    return sediment_fraction(world_, settings_.radius_max, exclusion);
  }
  const World& world() const { return world_; }
  const SedimentSettings& settings() const { return settings_; }
  double terminal_speed() const { return terminal_speed_; }
  double dt() const { return dt_; }
  long steps() const { return steps_; }
  double max_overlap() const { return max_overlap_; }
  double mean_height() const;

  static constexpr double kSettleWindow = 2.0;
  static constexpr double kSettleHeight = 1e-3;

 private:
  SedimentSettings settings_;
  World world_;
  double terminal_speed_ = 0.0;
  std::unique_ptr<SuspendingFluid> fluid_;
  TimeStepper stepper_;
  StepReport last_;
  double dt_ = 0.0;  // each step's, unless a redo shortens it
  long steps_ = 0;
  double max_overlap_ = 0.0;
  double max_time_ = 0.0;
  double window_start_time_ = 0.0, window_start_height_ = 0.0;
  bool settled_ = false;
};

}  // namespace dilatant
