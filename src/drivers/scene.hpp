#pragma once
// A scene as an object: particles from a CSV file, fixed planes, gravity, a box
// (docs/model.md; the validation and teaching mode). Build it, step it to
// run.time, read its state; the CLI's run loop (drivers/scene_run.hpp) writes
// its files.
//
//     Scene scene(config);                 // reads scene.particles, picks dt
//     while (!scene.done()) scene.step();
#include <memory>
#include <nlohmann/json.hpp>

#include "fluid/suspending_fluid.hpp"
#include "io/config.hpp"
#include "solver/time_stepper.hpp"

namespace dilatant {

// Running totals of the per-step solver and energy reports.
struct StepStatistics {
  long steps = 0;
  long unconverged = 0;
  long redone = 0;  // steps whose solve was redone at half the step
  long iterations_total = 0;
  int iterations_max = 0;
  double residual_max = 0.0;
  double contact_residual_max = 0.0;  // solver/contact_residual.hpp
  double overlap_max = 0.0;

  void add(const StepReport& r);
};

class Scene {
 public:
  // Throws InputError for a bad particles file or a trajectory_interval
  // shorter than the time step.
  explicit Scene(Config config);

  // One step of dt(), or, if its solve had to be redone at a shorter step
  // (solver/time_stepper.hpp), of that; the next calls then step the rest of
  // dt(), so that whole steps end on the time grid k dt.
  const StepReport& step();
  bool done() const { return whole_steps_ >= total_steps_; }

  const Config& config() const { return config_; }
  const World& world() const { return world_; }
  double dt() const { return dt_; }
  const std::vector<Contact>& contacts() const { return stepper_.contacts(); }
  const StepStatistics& statistics() const { return statistics_; }
  // summary.json: run totals, solver convergence, version.
  nlohmann::json summary(double wall_time_s) const;

 private:
  Config config_;
  World world_;
  TimeStepper stepper_;
  std::unique_ptr<SuspendingFluid> fluid_;  // null: no fluid forces
  double dt_ = 0.0;
  long total_steps_ = 0, whole_steps_ = 0;
  double rest_of_step_ = 0.0;  // of the current whole step, still to be stepped
  StepStatistics statistics_;
  StepReport last_;
};

}  // namespace dilatant
