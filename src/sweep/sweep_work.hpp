#pragma once
// The points of a sweep as one process holds them, and the running of its
// units of work. This is the part every scheduler shares: the local one
// (sweep_runner.cpp: worker threads pulling units from a counter) and the MPI
// one (mpi_scheduler.cpp: ranks asking rank 0 for units), so that a point runs
// with the same code, the same files and the same rules whichever hands it out.
//
// A unit is one point, or with continuation one chain (a flow curve's points
// in order of lambda, each starting from the previous one's final state): a
// chain is never split, so a continued point never waits for a point running
// elsewhere.
//
// Threads: run_unit is called by worker threads, several at a time, on
// different units; one watching thread calls wait_for_events and reports
// (writes the table, prints, or sends the changes to rank 0). Records are
// guarded by one mutex; what changed since the last wait is handed out once.
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <mutex>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "io/folder_lock.hpp"
#include "sweep/cold_start_choice.hpp"
#include "sweep/flow_table.hpp"
#include "sweep/point_folder.hpp"
#include "sweep/sweep_plan.hpp"
#include "sweep/sweep_runner.hpp"

namespace dilatant::sweep {

using WorkUnit = std::vector<std::size_t>;  // point indices, run in this order

// What changed since the watcher last looked.
struct SweepEvents {
  bool table_changed = false;               // a point finished: rewrite flowcurves.csv
  std::vector<std::size_t> changed_points;  // records that changed (running, finished)
  std::vector<std::string> notes;           // one-line messages for stderr
  std::size_t active_workers = 0;           // worker threads not yet ended
};

class SweepWork {
 public:
  SweepWork(const SweepPlan& plan, const SweepRunOptions& options);

  // The coordinator's start (the local sweep, or rank 0): inspects every point
  // folder (InputError, before anything is written, for a folder of another
  // configuration), writes sweep.toml, reads the finished points' summaries
  // and writes the table. Returns how many points were done before.
  std::size_t load_folders();

  // The units still to run: one point each, or with continuation one chain
  // each, leaving out finished points (a finished jam whose cold start has
  // not run stays, for its confirmation). Call after load_folders.
  std::vector<WorkUnit> work_units() const;

  // Runs the points of `unit` in order (from a worker thread). With
  // `inspect_first`, the folders of the unit's chain are read first: a rank
  // that did not call load_folders learns there what is done or resumable.
  void run_unit(const WorkUnit& unit, bool inspect_first);

  // Worker threads announce their start and end (the watcher stops when all ended).
  void worker_started();
  void worker_ended();

  // Waits up to `timeout` for a change and hands out what changed since the
  // last call.
  SweepEvents wait_for_events(std::chrono::milliseconds timeout);

  // Running points write a checkpoint and stop; no new point starts.
  void halt() { halt_.store(true); }
  bool halted() const { return halt_.load(); }

  PointRecord record(std::size_t i) const;
  std::vector<PointStatus> statuses() const;
  // A record that changed on another rank (rank 0 keeps the table).
  void set_record(std::size_t i, PointRecord record);
  void add_note(std::string note);

  // The fraction of its strain a point has run, -1 before it started here.
  double fraction(std::size_t i) const { return fraction_[i].load(); }
  void set_fraction(std::size_t i, double f) { fraction_[i].store(f); }
  // The points this process is running, with their fractions.
  std::vector<std::pair<std::size_t, double>> running_fractions() const;

  // Counts per status; the table, from this process's records.
  SweepOutcome outcome() const;
  void write_table() const;

  const SweepPlan& plan() const { return plan_; }

 private:
  // Inspects point i's folder and, when done, reads its summary (and its
  // jam's cold start). Returns whether it is done.
  bool load_point(std::size_t i);
  bool needs_confirmation(std::size_t i) const;
  // Point i as its folder runs it: planned, or extended (unsteady_extension.hpp).
  Config config_of(std::size_t i) const;
  // A finished point that is not steady, whose run may still go on (no
  // point continues from it yet): sweep.extend_unsteady_to.
  bool needs_extension(std::size_t i) const;
  bool successor_started(std::size_t i) const;
  // Point i's run ended with `summary`: it runs on while it is not steady
  // (sweep.extend_unsteady_to), then is recorded done; false when stopped
  // meanwhile (recorded pending, its folder resumable).
  bool finish_run(std::size_t i, nlohmann::json summary);
  ColdStartChoice cold_choice(std::size_t i, bool search) const;
  void confirm_jam(std::size_t i);
  void run_point(std::size_t i);
  void finish(std::size_t i, PointStatus status, const std::string& error,
              nlohmann::json summary = {});
  void changed(std::size_t i, bool table_changed);  // call with mutex_ held

  const SweepPlan& plan_;
  const SweepRunOptions& options_;
  std::vector<PointState> state_;              // each element touched by one thread at a time
  std::vector<int> extensions_;                // of each point's run; as state_
  std::vector<PointRecord> records_;           // guarded by mutex_
  std::vector<std::atomic<double>> fraction_;  // of each run's strain; -1 before it starts
  std::atomic<bool> halt_;
  mutable std::mutex mutex_;
  std::condition_variable changed_;
  SweepEvents events_;              // guarded by mutex_; active_workers is the live count
  std::optional<FolderLock> lock_;  // the sweep folder's, from load_folders on
};

}  // namespace dilatant::sweep
