// The sweep's scheduler (sweep_runner.hpp). Workers take units of work (a
// point, or a chain of continued points) from a shared counter; the calling
// thread watches: it writes flowcurves.csv when a point finishes, prints
// failures and the progress line, and turns an external stop into the stop
// flag the runs see.
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

#include <fmt/format.h>

#include <chrono>
#include <condition_variable>
#include <fstream>
#include <iostream>
#include <mutex>
#include <sstream>
#include <thread>

#include "drivers/shear_cell_run.hpp"
#include "io/atomic_file.hpp"
#include "sweep/flow_table.hpp"
#include "sweep/point_folder.hpp"

namespace dilatant::sweep {
namespace {

using Clock = std::chrono::steady_clock;

std::string duration_text(double seconds) {
  const auto s = static_cast<long>(seconds + 0.5);
  if (s < 60) return fmt::format("{}s", s);
  if (s < 3600) return fmt::format("{}m{:02}s", s / 60, s % 60);
  return fmt::format("{}h{:02}m", s / 3600, (s % 3600) / 60);
}

nlohmann::json read_summary(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::ostringstream text;
  text << in.rdbuf();
  return nlohmann::json::parse(text.str());  // throws on a corrupt file
}

// A message on one line.
std::string one_line(std::string text) {
  for (char& c : text)
    if (c == '\n' || c == '\r') c = ' ';
  return text;
}

class Sweep {
 public:
  Sweep(const SweepPlan& plan, const SweepRunOptions& options)
      : plan_(plan),
        options_(options),
        state_(plan.points.size(), PointState::Fresh),
        records_(plan.points.size()),
        fraction_(plan.points.size()),
        baseline_(plan.points.size(), -1.0),
        halt_(options.stop != nullptr && options.stop->load()) {}

  SweepOutcome run() {
    const auto& out = options_.out;
    for (const auto& p : plan_.points) state_[p.index] = inspect_point_folder(p, out / p.folder);
    std::filesystem::create_directories(out / "points");
    write_file_atomically(out / "sweep.toml", resolved_sweep_toml(plan_));
    SweepOutcome outcome;
    outcome.points = plan_.points.size();
    for (const auto& p : plan_.points) {
      fraction_[p.index].store(-1.0);
      if (state_[p.index] != PointState::Done) continue;
      try {
        records_[p.index].summary = read_summary(out / p.folder / "summary.json");
      } catch (const std::exception&) {
        state_[p.index] = PointState::Fresh;  // an unreadable summary.json: run the point anew
        continue;
      }
      records_[p.index].status = PointStatus::Done;
      ++outcome.skipped;
      if (needs_confirmation(p.index) &&
          inspect_point_folder(cold_point(p), out / p.folder / kColdStart) == PointState::Done) {
        try {
          records_[p.index].cold_start = read_summary(out / p.folder / kColdStart / "summary.json");
        } catch (const std::exception&) {
          // unreadable: the confirmation runs again
        }
      }
    }
    write_table();

    const auto units = work_units();
    const std::size_t workers =
        std::min<std::size_t>(static_cast<std::size_t>(std::max(options_.jobs, 1)), units.size());
    active_ = workers;
    start_ = Clock::now();
    std::vector<std::thread> threads;
    for (std::size_t w = 0; w < workers; ++w)
      threads.emplace_back([this, &units] {
        for (std::size_t u; (u = next_unit_.fetch_add(1)) < units.size();)
          for (std::size_t i : units[u]) run_point(i);
        std::lock_guard lock(mutex_);
        --active_;
        changed_.notify_all();
      });
    watch();
    for (auto& t : threads) t.join();
    write_table();
    if (progress_shown_) std::cerr << "\n";

    for (const auto& r : records_) {
      outcome.done += r.status == PointStatus::Done;
      outcome.failed += r.status == PointStatus::Failed;
      outcome.pending += r.status == PointStatus::Pending || r.status == PointStatus::Running;
      outcome.above_jam += r.status == PointStatus::Skipped;
    }
    outcome.interrupted = halt_.load() && outcome.pending > 0;
    return outcome;
  }

 private:
  // One point each, or with continuation one chain each (in order of lambda),
  // leaving out the finished ones.
  std::vector<std::vector<std::size_t>> work_units() const {
    std::vector<std::vector<std::size_t>> units;
    std::vector<std::optional<std::size_t>> next(plan_.points.size());
    for (const auto& p : plan_.points)
      if (p.continues_from) next[*p.continues_from] = p.index;
    for (const auto& p : plan_.points) {
      if (p.continues_from) continue;  // runs in its chain
      std::vector<std::size_t> unit;
      for (std::optional<std::size_t> i = p.index; i; i = next[*i])
        if (state_[*i] != PointState::Done || needs_confirmation(*i)) unit.push_back(*i);
      if (!unit.empty()) units.push_back(std::move(unit));
    }
    return units;
  }

  static constexpr const char* kColdStart = "cold-start";

  // A continued point that jammed, whose cold start has not run yet.
  bool needs_confirmation(std::size_t i) const {
    std::lock_guard lock(mutex_);
    return plan_.settings.confirm_jams && plan_.points[i].continues_from && jammed(records_[i]) &&
           !records_[i].cold_start.is_object();
  }

  static SweepPoint cold_point(const SweepPoint& p) {
    SweepPoint cold = p;
    cold.config = p.cold_start.value_or(p.config);
    cold.continues_from.reset();
    return cold;
  }

  // The jam of continued point i, run again from a new packing in its
  // folder's cold-start/ (resumable like a point): a ramp's jam is reported
  // with whether the same stress jams a cold start too.
  void confirm_jam(std::size_t i) {
    const SweepPoint cold = cold_point(plan_.points[i]);
    const auto folder = options_.out / plan_.points[i].folder / kColdStart;
    const PointState state = inspect_point_folder(cold, folder);
    try {
      if (state != PointState::Done) {
        CellRunOptions o;
        o.run.out_dir = folder;
        o.run.quiet = true;
        o.resume = state == PointState::Resumable;
        o.stop_requested = &halt_;
        if (run_shear_cell(cold.config, o).interrupted) return;
      }
      auto summary = read_summary(folder / "summary.json");
      std::lock_guard lock(mutex_);
      records_[i].cold_start = std::move(summary);
      dirty_ = true;
      changed_.notify_all();
    } catch (const std::exception& e) {
      std::lock_guard lock(mutex_);
      notes_.push_back(fmt::format("dilatant: the cold start confirming the jam of {} failed: {}",
                                   plan_.points[i].folder, one_line(e.what())));
    }
  }

  void run_point(std::size_t i) {
    if (halt_.load()) return;
    const SweepPoint& p = plan_.points[i];
    const auto folder = options_.out / p.folder;
    if (state_[i] == PointState::Done) {  // in the unit for its jam's cold start only
      confirm_jam(i);
      return;
    }
    std::filesystem::path start_from;
    if (p.continues_from) {
      const SweepPoint& before = plan_.points[*p.continues_from];
      PointRecord previous;
      {
        std::lock_guard lock(mutex_);
        previous = records_[before.index];
      }
      if (previous.status == PointStatus::Skipped ||
          (plan_.settings.stop_at_jam && jammed(previous))) {
        finish(i, PointStatus::Skipped,
               previous.status == PointStatus::Skipped
                   ? previous.error
                   : fmt::format("not run: the ramp jammed at {} (lambda {})", before.folder,
                                 before.config.fluid.lambda));
        return;
      }
      if (previous.status != PointStatus::Done) {
        if (previous.status == PointStatus::Failed)
          finish(i, PointStatus::Failed,
                 fmt::format("not run: it continues from {}, which failed", before.folder));
        return;  // the predecessor was interrupted: stays pending
      }
      start_from = options_.out / before.folder / "checkpoint.bin";
    }
    {
      std::lock_guard lock(mutex_);
      records_[i].status = PointStatus::Running;
    }
    std::error_code ignored;
    std::filesystem::remove(folder / "error.txt", ignored);
    try {
      CellRunOptions o;
      o.run.out_dir = folder;
      o.run.quiet = true;
      o.resume = state_[i] == PointState::Resumable;
      o.stop_requested = &halt_;
      o.start_from = o.resume ? std::filesystem::path() : start_from;
      o.progress = &fraction_[i];
      CellOutcome outcome = run_shear_cell(p.config, o);
      if (o.resume && !outcome.interrupted &&
          !std::filesystem::is_regular_file(folder / "summary.json")) {
        // The checkpoint is the final state of a run whose result files are
        // gone (summary.json deleted to redo the point): run it anew.
        o.resume = false;
        o.start_from = start_from;
        outcome = run_shear_cell(p.config, o);
      }
      if (outcome.interrupted) {
        finish(i, PointStatus::Pending, "");
        return;
      }
      if (!std::filesystem::is_regular_file(folder / "summary.json"))
        throw std::runtime_error("the run ended without writing summary.json");
      finish(i, PointStatus::Done, "", read_summary(folder / "summary.json"));
    } catch (const std::exception& e) {
      finish(i, PointStatus::Failed, one_line(e.what()));
      return;
    }
    if (needs_confirmation(i)) confirm_jam(i);
  }

  void finish(std::size_t i, PointStatus status, const std::string& error,
              nlohmann::json summary = {}) {
    if (status == PointStatus::Failed) {
      std::error_code ignored;
      std::filesystem::create_directories(options_.out / plan_.points[i].folder, ignored);
      try {
        write_file_atomically(options_.out / plan_.points[i].folder / "error.txt", error + "\n");
      } catch (const std::exception&) {
        // the table still records it
      }
    }
    std::lock_guard lock(mutex_);
    records_[i].status = status;
    records_[i].error = error;
    records_[i].summary = std::move(summary);
    if (status == PointStatus::Failed)
      notes_.push_back(fmt::format("dilatant: point {} failed: {}", plan_.points[i].folder, error));
    dirty_ = true;
    changed_.notify_all();
  }

  void write_table() {
    write_file_atomically(options_.out / "flowcurves.csv", flowcurves_csv(plan_, records_));
  }

  // The calling thread, until every worker has ended.
  void watch() {
    std::unique_lock lock(mutex_);
    auto last_line = Clock::now() - std::chrono::seconds(10);
    while (active_ > 0) {
      changed_.wait_for(lock, std::chrono::milliseconds(100));
      if (options_.stop != nullptr && options_.stop->load()) halt_.store(true);
      if (dirty_) {
        dirty_ = false;
        try {
          write_table();
        } catch (const std::exception& e) {
          notes_.push_back(fmt::format("dilatant: cannot write flowcurves.csv: {}", e.what()));
          halt_.store(true);
        }
      }
      for (const auto& note : notes_)
        if (options_.report_failures || options_.show_progress)
          std::cerr << (progress_shown_ ? "\r\033[K" : "") << note << "\n";
      notes_.clear();
      if (options_.show_progress && Clock::now() - last_line >= std::chrono::seconds(1)) {
        std::cerr << "\r\033[K" << progress_line() << std::flush;
        progress_shown_ = true;
        last_line = Clock::now();
      }
    }
  }

  // "sweep: 3/12 done, 2 running, 1 failed; 1m05s elapsed, about 4m left"
  std::string progress_line() {
    std::size_t done = 0, running = 0, failed = 0;
    double progressed = 0.0, remaining = 0.0;
    for (std::size_t i = 0; i < records_.size(); ++i) {
      const PointStatus s = records_[i].status;
      done += s == PointStatus::Done;
      running += s == PointStatus::Running;
      failed += s == PointStatus::Failed;
      const double f = fraction_[i].load();
      if (f >= 0.0 && baseline_[i] < 0.0) baseline_[i] = f;  // where this invocation took it up
      if (baseline_[i] >= 0.0) progressed += std::max(0.0, f - baseline_[i]);
      if (s == PointStatus::Pending || s == PointStatus::Running)
        remaining += 1.0 - std::max(0.0, f);
    }
    const double elapsed = std::chrono::duration<double>(Clock::now() - start_).count();
    const std::string left =
        progressed > 0.0 ? "about " + duration_text(elapsed * remaining / progressed) : "unknown";
    return fmt::format("sweep: {}/{} done, {} running, {} failed; {} elapsed, {} left", done,
                       records_.size(), running, failed, duration_text(elapsed),
                       remaining > 0.0 ? left : "nothing");
  }

  const SweepPlan& plan_;
  const SweepRunOptions& options_;
  std::vector<PointState> state_;
  std::vector<PointRecord> records_;           // guarded by mutex_
  std::vector<std::atomic<double>> fraction_;  // of each run's strain; -1 before it starts
  std::vector<double> baseline_;               // the watcher's
  std::atomic<bool> halt_;
  std::atomic<std::size_t> next_unit_{0};
  mutable std::mutex mutex_;
  std::condition_variable changed_;
  std::size_t active_ = 0;  // guarded by mutex_
  bool dirty_ = false;      // guarded by mutex_
  std::vector<std::string> notes_;
  bool progress_shown_ = false;
  Clock::time_point start_;
};

}  // namespace

SweepOutcome run_sweep(const SweepPlan& plan, const SweepRunOptions& options) {
  Sweep sweep(plan, options);
  return sweep.run();
}

}  // namespace dilatant::sweep
