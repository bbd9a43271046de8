#include "sweep/mpi_scheduler.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <atomic>
#include <condition_variable>
#include <deque>
#include <iostream>
#include <mutex>
#include <optional>
#include <thread>

#include "io/input_error.hpp"
#include "sweep/mpi_messages.hpp"
#include "sweep/sweep_watch.hpp"
#include "sweep/sweep_work.hpp"

namespace dilatant::sweep {
namespace {

using Clock = std::chrono::steady_clock;
// How often the main thread of each rank looks at its messages: short next to
// a point (seconds to hours), long enough to leave its core to the points.
constexpr auto kPoll = std::chrono::milliseconds(10);

// Rank 0: keeps the table and hands out the units, to its own threads and to
// the ranks that ask.
class Coordinator {
 public:
  Coordinator(const SweepPlan& plan, const SweepRunOptions& options, const MpiSession& session)
      : work_(plan, options), options_(options), ranks_running_(session.size() - 1) {}

  SweepOutcome run() {
    std::size_t skipped = 0;
    try {
      skipped = work_.load_folders();
    } catch (...) {
      serve(nullptr);  // no units: every request gets kNoMore and the ranks end
      throw;
    }
    units_ = work_.work_units();
    SweepWatch watch(work_, options_);
    std::vector<std::thread> threads;
    const auto jobs = static_cast<std::size_t>(std::max(options_.jobs, 1));
    for (std::size_t w = 0; w < std::min(jobs, units_.size()); ++w) {
      work_.worker_started();
      threads.emplace_back([this] {
        for (std::optional<std::size_t> u; (u = take_unit());) work_.run_unit(units_[*u], false);
        work_.worker_ended();
      });
    }
    try {
      serve(&watch);
    } catch (...) {
      work_.halt();  // the running points write their checkpoints
      for (auto& t : threads) t.join();
      throw;
    }
    for (auto& t : threads) t.join();
    work_.write_table();
    watch.finish();

    SweepOutcome outcome = work_.outcome();
    outcome.skipped = skipped;
    outcome.interrupted = (work_.halted() || a_rank_halted_) && outcome.pending > 0;
    return outcome;
  }

 private:
  // The next unit, in the order of the plan, to whoever asks first; none
  // once the sweep halts.
  std::optional<std::size_t> take_unit() {
    if (work_.halted()) return std::nullopt;
    const std::size_t u = next_unit_.fetch_add(1);
    return u < units_.size() ? std::optional(u) : std::nullopt;
  }

  // The main thread, until its own threads and every other rank have ended.
  void serve(SweepWatch* watch) {
    std::vector<bool> halted(static_cast<std::size_t>(ranks_running_) + 1, false);
    for (;;) {
      for (mpi::Message m; mpi::try_receive(MPI_ANY_SOURCE, m);) handle(m, halted);
      const SweepEvents events = work_.wait_for_events(kPoll);
      if (watch != nullptr) watch->tick(events);
      if (work_.halted())
        for (int r = 1; r < static_cast<int>(halted.size()); ++r)
          if (!halted[static_cast<std::size_t>(r)]) {
            mpi::send(r, mpi::kHalt);
            halted[static_cast<std::size_t>(r)] = true;
          }
      if (events.active_workers == 0 && ranks_running_ == 0) break;
    }
    // The sweep is over: the other ranks, which wait for this word sleeping
    // rather than spinning in MPI_Finalize, may end.
    for (int r = 1; r < static_cast<int>(halted.size()); ++r) mpi::send(r, mpi::kFinished);
  }

  void handle(const mpi::Message& m, std::vector<bool>& halted) {
    switch (m.tag) {
      case mpi::kRequest:
        if (const auto u = take_unit())
          mpi::send(m.from, mpi::kAssign, mpi::unit_text(units_[*u]));
        else
          mpi::send(m.from, mpi::kNoMore);
        break;
      case mpi::kRecord: {
        auto [i, record] = mpi::parse_record(m.payload);
        work_.set_record(i, std::move(record));
        break;
      }
      case mpi::kNote:
        work_.add_note(m.payload);
        break;
      case mpi::kProgress: {
        const nlohmann::json fractions = nlohmann::json::parse(m.payload);
        for (const auto& [i, f] : fractions.items())
          work_.set_fraction(std::stoul(i), f.get<double>());
        break;
      }
      case mpi::kFinished:
        a_rank_halted_ = a_rank_halted_ || m.payload == "halted";
        halted[static_cast<std::size_t>(m.from)] = true;  // no kHalt for it any more
        --ranks_running_;
        break;
      default:
        break;
    }
  }

  SweepWork work_;
  const SweepRunOptions& options_;
  std::vector<WorkUnit> units_;
  std::atomic<std::size_t> next_unit_{0};
  int ranks_running_;
  bool a_rank_halted_ = false;
};

// The units a worker rank was given, for its threads.
class UnitQueue {
 public:
  // The next unit; none once closed.
  std::optional<WorkUnit> pop() {
    std::unique_lock lock(mutex_);
    ++waiting_;
    ready_.wait(lock, [this] { return !units_.empty() || closed_; });
    --waiting_;
    if (units_.empty()) return std::nullopt;
    WorkUnit unit = std::move(units_.front());
    units_.pop_front();
    return unit;
  }
  void push(WorkUnit unit) {
    std::lock_guard lock(mutex_);
    units_.push_back(std::move(unit));
    ready_.notify_one();
  }
  void close() {
    std::lock_guard lock(mutex_);
    closed_ = true;
    ready_.notify_all();
  }
  // Threads waiting for a unit not yet in the queue.
  int hungry() const {
    std::lock_guard lock(mutex_);
    return waiting_ - static_cast<int>(units_.size());
  }

 private:
  mutable std::mutex mutex_;
  std::condition_variable ready_;
  std::deque<WorkUnit> units_;
  int waiting_ = 0;
  bool closed_ = false;
};

// Rank r > 0: asks rank 0 for a unit whenever one of its threads is free,
// runs it, and reports every change of a point's record.
class Worker {
 public:
  Worker(const SweepPlan& plan, const SweepRunOptions& options)
      : work_(plan, options), options_(options) {}

  SweepOutcome run() {
    std::vector<std::thread> threads;
    for (int w = 0; w < std::max(options_.jobs, 1); ++w) {
      work_.worker_started();
      threads.emplace_back([this] {
        while (const auto unit = queue_.pop()) work_.run_unit(*unit, true);
        work_.worker_ended();
      });
    }
    bool halted_here = false;
    try {
      halted_here = serve();
    } catch (...) {
      work_.halt();  // the running points write their checkpoints
      queue_.close();
      for (auto& t : threads) t.join();
      throw;
    }
    for (auto& t : threads) t.join();
    report(work_.wait_for_events(std::chrono::milliseconds(0)));
    // Rank 0 answers every request, and sends kFinished last, once every rank
    // ended: nothing is left in flight, and this rank sleeps meanwhile (a rank
    // waiting in MPI_Finalize would spin on a core the others need).
    while (requested_ > 0) receive_and_handle();
    mpi::send(0, mpi::kFinished, halted_here ? "halted" : "");
    while (!finished_) receive_and_handle();
    return work_.outcome();
  }

 private:
  // The main thread, until its threads ended. Returns whether this rank
  // stopped on its own signal.
  bool serve() {
    bool halted_here = false;
    auto last_progress = Clock::now();
    for (;;) {
      const SweepEvents events = work_.wait_for_events(kPoll);
      if (options_.stop != nullptr && options_.stop->load() && !work_.halted()) {
        work_.halt();  // its own SIGTERM (a job's time limit): checkpoint and end
        halted_here = true;
      }
      report(events);
      if (Clock::now() - last_progress >= std::chrono::seconds(1)) {
        nlohmann::json fractions = nlohmann::json::object();
        for (const auto& [i, f] : work_.running_fractions()) fractions[std::to_string(i)] = f;
        if (!fractions.empty()) mpi::send(0, mpi::kProgress, fractions.dump());
        last_progress = Clock::now();
      }
      for (mpi::Message m; mpi::try_receive(0, m);) handle(m);
      if (work_.halted() || no_more_) {
        queue_.close();  // the waiting threads end, the running ones after their unit
      } else {
        for (; requested_ < queue_.hungry(); ++requested_) mpi::send(0, mpi::kRequest);
      }
      if (events.active_workers == 0) return halted_here;
    }
  }

  void report(const SweepEvents& events) {
    std::vector<std::size_t> points = events.changed_points;
    std::sort(points.begin(), points.end());
    points.erase(std::unique(points.begin(), points.end()), points.end());
    for (std::size_t i : points) mpi::send(0, mpi::kRecord, mpi::record_json(i, work_.record(i)));
    for (const auto& note : events.notes) mpi::send(0, mpi::kNote, note);
  }

  void receive_and_handle() {
    mpi::Message m;
    while (!mpi::try_receive(0, m)) std::this_thread::sleep_for(kPoll);
    handle(m);
  }

  void handle(const mpi::Message& m) {
    switch (m.tag) {
      case mpi::kAssign:
        --requested_;
        queue_.push(mpi::parse_unit(m.payload));  // after a halt, stays in the queue unrun
        break;
      case mpi::kNoMore:
        --requested_;
        no_more_ = true;
        break;
      case mpi::kHalt:
        work_.halt();
        break;
      case mpi::kFinished:
        finished_ = true;
        break;
      default:
        break;
    }
  }

  SweepWork work_;
  const SweepRunOptions& options_;
  UnitQueue queue_;
  int requested_ = 0;  // requests not answered yet
  bool no_more_ = false;
  bool finished_ = false;
};

}  // namespace

SweepOutcome run_sweep_on_ranks(const SweepPlan& plan, const SweepRunOptions& options,
                                const MpiSession& session) {
  if (session.rank() == 0) {
    Coordinator coordinator(plan, options, session);
    try {
      return coordinator.run();
    } catch (const InputError&) {
      throw;  // from reading the folders: the other ranks were told and end
    } catch (const std::exception& e) {
      std::cerr << fmt::format("dilatant: failed on rank 0: {}\n", e.what());
    }
  } else {
    try {
      return Worker(plan, options).run();
    } catch (const std::exception& e) {
      std::cerr << fmt::format("dilatant: failed on rank {}: {}\n", session.rank(), e.what());
    }
  }
  // A fault of the scheduler itself (the points' own errors are recorded, not
  // thrown): the other ranks would wait for this one forever. The running
  // points wrote their checkpoints; the same command resumes.
  MPI_Abort(MPI_COMM_WORLD, 1);
  return {};
}

}  // namespace dilatant::sweep
