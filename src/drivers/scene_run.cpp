#include "drivers/scene_run.hpp"

#include <fmt/format.h>
#include <toml++/toml.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>

#include "drivers/scene.hpp"
#include "drivers/scene_checkpoint.hpp"
#include "io/atomic_file.hpp"
#include "io/checksum.hpp"
#include "io/config_compare.hpp"
#include "io/contacts_csv.hpp"
#include "io/folder_lock.hpp"
#include "io/input_error.hpp"
#include "io/output_folder.hpp"
#include "io/text.hpp"
#include "io/trajectory_writer.hpp"
#include "measure/run_cost.hpp"

namespace dilatant {

namespace {

constexpr const char* kTimeseriesHeader =
    "step,t,contacts,iterations,residual,converged,kinetic_energy,max_overlap,"
    "contact_residual_normal,contact_residual_tangential\n";

// The checkpoint in `out`, checked against this run's configuration (its
// config.toml; only run.time may grow); restore_scene checks the particles
// file. Anything that does not fit is bad input naming its file.
SceneCheckpoint resumable_checkpoint(const Config& config, const std::filesystem::path& out) {
  static constexpr std::string_view kExtensible[] = {"run.time"};
  if (const auto there = resumable_run_config(out, config, kExtensible, "only run.time may grow")) {
    const double before = (*there)["run"]["time"].value_or(0.0);
    if (config.run.time < before)
      throw InputError(fmt::format(
          "{}: run.time = {} is below the run's there ({}): --resume extends a run, it cannot "
          "shorten one",
          (out / "config.toml").string(), config.run.time, before));
  }
  return load_scene_checkpoint(out / "checkpoint.bin");
}

}  // namespace

SceneOutcome run_scene(const Config& config, const SceneRunOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  const auto& out = options.run.out_dir;
  const auto checkpoint_file = out / "checkpoint.bin";
  prepare_output_folder(out);
  // Held to the end of the run: a second run on this folder would resume from
  // the same checkpoint and overwrite this one's (io/folder_lock.hpp).
  const FolderLock lock(out, "a scene run");

  Scene scene(config);
  const double dt = scene.dt();
  const double frame_interval = config.scene()->trajectory_interval;
  const std::uint32_t crc = scene_particles_crc(config);
  std::optional<SceneCheckpoint> resumed;
  if (options.resume && std::filesystem::exists(checkpoint_file)) {
    resumed = resumable_checkpoint(config, out);
    // Its progress moves into the scene; the byte counts and next frame stay.
    restore_scene(scene, std::move(*resumed), config, checkpoint_file);
    // Nothing left to run: keep the finished run's files as they are.
    if (scene.done())
      return SceneOutcome{scene.statistics().steps, scene.statistics().unconverged, false};
    // A finished run extended: its end results describe the shorter run.
    remove_earlier_results(out, {"summary.json", "contacts.csv"});
  } else {
    remove_earlier_results(out, {"checkpoint.bin", "timeseries.csv", "trajectory.csv",
                                 "contacts.csv", "summary.json"});
  }
  write_file_atomically(out / "config.toml", resolved_toml(config));

  std::optional<TrajectoryWriter> trajectory;
  std::optional<AtomicFileWriter> timeseries;
  double next_frame = frame_interval;
  if (resumed) {
    trajectory.emplace(out / "trajectory.csv", resumed->trajectory_bytes);
    timeseries.emplace(out / "timeseries.csv", resumed->timeseries_bytes);
    next_frame = resumed->next_frame;
  } else {
    trajectory.emplace(out / "trajectory.csv");
    timeseries.emplace(out / "timeseries.csv");
    timeseries->write(kTimeseriesHeader);
    trajectory->write_frame(scene.world());
  }
  const auto write_checkpoint = [&] {
    save_scene_checkpoint(checkpoint_file,
                          SceneCheckpoint{scene.progress(), crc, next_frame,
                                          timeseries->flushed_size(), trajectory->flushed_size()});
  };

  while (!scene.done()) {
    const StepReport& r = scene.step();
    const double t = scene.world().time;
    timeseries->write(fmt::format("{},{:.10g},{},{},{:.3e},{},{:.10g},{:.3e},{:.3e},{:.3e}\n",
                                  scene.statistics().steps, t, r.contacts_closed,
                                  r.solve.iterations, r.solve.residual, r.solve.converged ? 1 : 0,
                                  r.kinetic_energy, r.max_overlap, r.contact_residual.normal_max,
                                  r.contact_residual.tangential_max));
    // Frames fall on the first step at or past each multiple of the interval;
    // a checkpoint goes with each (it is smaller than the frame).
    if (t >= next_frame - 1e-9 * dt) {
      trajectory->write_frame(scene.world());
      next_frame += frame_interval * std::floor((t - next_frame) / frame_interval + 1.0 + 1e-9);
      write_checkpoint();
    }
    if (options.progress != nullptr) options.progress->store(std::min(1.0, t / config.run.time));
    if (options.stop_requested != nullptr && options.stop_requested->load()) {
      write_checkpoint();
      trajectory->keep();
      timeseries->keep();
      return SceneOutcome{scene.statistics().steps, scene.statistics().unconverged, true};
    }
  }
  // The checkpoint of the end: a --resume with a larger run.time runs on from it.
  write_checkpoint();
  trajectory->commit();
  timeseries->commit();
  write_file_atomically(out / "contacts.csv",
                        contacts_csv(scene.world().bodies, scene.contacts(), dt));
  const double wall = seconds_since(start);
  write_file_atomically(out / "summary.json", scene.summary(wall).dump(2) + "\n");
  return SceneOutcome{scene.statistics().steps, scene.statistics().unconverged, false};
}

}  // namespace dilatant
