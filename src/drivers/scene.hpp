#pragma once
// A scene as an object: particles from a CSV file, fixed planes, gravity, a box
// (docs/model.md; the validation and teaching mode). Build it, step it to
// run.time, read its state; the CLI's run loop (drivers/scene_run.hpp) writes
// its files.
//
//     Scene scene(config);                 // reads scene.particles, picks dt
//     while (!scene.done()) scene.step();
#include <cstdint>
#include <memory>
#include <nlohmann/json.hpp>
#include <unordered_map>
#include <vector>

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

// What a scene carries from step to step beyond its configuration: the
// bodies' motion, the clock, the solver's contact memory (its warm start) and
// the running totals. Restored into a scene built from the same configuration,
// the run goes on with the bits it would have had uninterrupted
// (drivers/scene_checkpoint.hpp writes it).
struct SceneProgress {
  std::vector<Vec3> position, velocity, angular_velocity;
  double time = 0.0;
  long whole_steps = 0;
  double rest_of_step = 0.0;
  StepStatistics statistics;
  std::unordered_map<std::uint64_t, ContactMemory> contact_memory;
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
  SceneProgress progress() const;
  // Throws std::runtime_error if `p` has another number of bodies.
  void restore(SceneProgress p);
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
