// The sweep's local scheduler (sweep_runner.hpp): worker threads take units of
// work (a point, or a chain of continued points: sweep_work.hpp) from a shared
// counter; the calling thread watches (sweep_watch.hpp): it writes
// flowcurves.csv when a point finishes, prints failures and the progress line,
// and turns an external stop into the stop flag the runs see. The MPI
// scheduler (mpi_scheduler.cpp) hands out the same units to ranks instead.
//
//   calling thread            worker 1 .. jobs
//   ──────────────            ─────────────────────────────────────────
//   inspect folders           loop: unit = next++ ; for point in unit:
//   write sweep.toml,                 run_shear_cell(point)  (checkpoints,
//     flowcurves.csv                    progress fraction, stop flag)
//   start workers                     lock; record done/failed; notify
//   until all workers end:
//     wait 100 ms or notify
//     stop requested -> halt
//     table changed  -> write flowcurves.csv
//     each second    -> progress line
#include "sweep/sweep_runner.hpp"

#include <thread>

#include "sweep/sweep_watch.hpp"
#include "sweep/sweep_work.hpp"

namespace dilatant::sweep {

SweepOutcome run_sweep(const SweepPlan& plan, const SweepRunOptions& options) {
  SweepWork work(plan, options);
  const std::size_t skipped = work.load_folders();
  const std::vector<WorkUnit> units = work.work_units();
  const std::size_t workers =
      std::min<std::size_t>(static_cast<std::size_t>(std::max(options.jobs, 1)), units.size());
  SweepWatch watch(work, options);
  std::atomic<std::size_t> next_unit{0};
  std::vector<std::thread> threads;
  for (std::size_t w = 0; w < workers; ++w) {
    work.worker_started();
    threads.emplace_back([&] {
      for (std::size_t u; (u = next_unit.fetch_add(1)) < units.size();)
        work.run_unit(units[u], false);
      work.worker_ended();
    });
  }
  for (bool running = workers > 0; running;) {
    const SweepEvents events = work.wait_for_events(std::chrono::milliseconds(100));
    watch.tick(events);
    running = events.active_workers > 0;
  }
  for (auto& t : threads) t.join();
  work.write_table();
  watch.finish();

  SweepOutcome outcome = work.outcome();
  outcome.skipped = skipped;
  outcome.interrupted = work.halted() && outcome.pending > 0;
  return outcome;
}

}  // namespace dilatant::sweep
