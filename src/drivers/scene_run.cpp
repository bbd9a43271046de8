#include "drivers/scene_run.hpp"

#include <fmt/format.h>

#include <chrono>
#include <cmath>

#include "drivers/scene.hpp"
#include "io/atomic_file.hpp"
#include "io/contacts_csv.hpp"
#include "io/output_folder.hpp"
#include "io/trajectory_writer.hpp"
#include "measure/run_cost.hpp"

namespace dilatant {

SceneOutcome run_scene(const Config& config, const RunOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  Scene scene(config);
  const double dt = scene.dt();
  const double frame_interval = config.scene()->trajectory_interval;

  prepare_output_folder(options.out_dir);
  write_file_atomically(options.out_dir / "config.toml", resolved_toml(config));
  TrajectoryWriter trajectory(options.out_dir / "trajectory.csv");
  AtomicFileWriter timeseries(options.out_dir / "timeseries.csv");
  timeseries.write(
      "step,t,contacts,iterations,residual,converged,kinetic_energy,max_overlap,"
      "contact_residual_normal,contact_residual_tangential\n");

  trajectory.write_frame(scene.world());
  double next_frame = frame_interval;
  while (!scene.done()) {
    const StepReport& r = scene.step();
    const double t = scene.world().time;
    timeseries.write(fmt::format("{},{:.10g},{},{},{:.3e},{},{:.10g},{:.3e},{:.3e},{:.3e}\n",
                                 scene.statistics().steps, t, r.contacts_closed, r.solve.iterations,
                                 r.solve.residual, r.solve.converged ? 1 : 0, r.kinetic_energy,
                                 r.max_overlap, r.contact_residual.normal_max,
                                 r.contact_residual.tangential_max));
    // Frames fall on the first step at or past each multiple of the interval.
    if (t >= next_frame - 1e-9 * dt) {
      trajectory.write_frame(scene.world());
      next_frame += frame_interval * std::floor((t - next_frame) / frame_interval + 1.0 + 1e-9);
    }
  }
  trajectory.commit();
  timeseries.commit();
  write_file_atomically(options.out_dir / "contacts.csv",
                        contacts_csv(scene.world().bodies, scene.contacts(), dt));
  const double wall = seconds_since(start);
  write_file_atomically(options.out_dir / "summary.json", scene.summary(wall).dump(2) + "\n");
  return SceneOutcome{scene.statistics().steps, scene.statistics().unconverged};
}

}  // namespace dilatant
