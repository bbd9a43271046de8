#include "sweep/sweep_work.hpp"

#include <fmt/format.h>

#include <cmath>
#include <limits>
#include <optional>
#include <set>

#include "drivers/shear_cell_run.hpp"
#include "io/atomic_file.hpp"
#include "io/folder_lock.hpp"
#include "io/output_folder.hpp"
#include "sweep/cold_start_choice.hpp"
#include "sweep/refined_start.hpp"
#include "sweep/unsteady_extension.hpp"

namespace dilatant::sweep {
namespace {

constexpr const char* kColdStart = "cold-start";

// A message on one line.
std::string one_line(std::string text) {
  for (char& c : text)
    if (c == '\n' || c == '\r') c = ' ';
  return text;
}

SweepPoint cold_point(const SweepPoint& p, Config config) {
  SweepPoint cold = p;
  cold.config = std::move(config);
  cold.continues_from.reset();
  return cold;
}

}  // namespace

SweepWork::SweepWork(const SweepPlan& plan, const SweepRunOptions& options)
    : plan_(plan),
      options_(options),
      state_(plan.points.size(), PointState::Fresh),
      extensions_(plan.points.size(), 0),
      records_(plan.points.size()),
      fraction_(plan.points.size()),
      halt_(options.stop != nullptr && options.stop->load()) {
  for (auto& f : fraction_) f.store(-1.0);
}

std::size_t SweepWork::load_folders() {
  const auto& out = options_.out;
  // Every folder is compared before anything is written: a changed sweep is
  // refused as a whole.
  refuse_refining_into_itself(plan_, out);
  prepare_output_folder(out);
  // One sweep per folder, held while this one lives (io/folder_lock.hpp): a
  // second would run the same points into the same folders.
  lock_.emplace(out, "a sweep");
  for (const auto& p : plan_.points) {
    const PointFolder f =
        inspect_point_folder(p, out / p.folder, plan_.settings.extend_unsteady_to);
    state_[p.index] = f.state;
    extensions_[p.index] = f.extensions;
  }
  std::filesystem::create_directories(out / "points");
  write_file_atomically(out / "sweep.toml", resolved_sweep_toml(plan_));
  std::size_t skipped = 0;
  for (const auto& p : plan_.points)
    if (state_[p.index] == PointState::Done) skipped += load_point(p.index);
  write_table();
  return skipped;
}

bool SweepWork::load_point(std::size_t i) {
  const SweepPoint& p = plan_.points[i];
  const auto folder = options_.out / p.folder;
  const PointFolder f = inspect_point_folder(p, folder, plan_.settings.extend_unsteady_to);
  state_[i] = f.state;
  extensions_[i] = f.extensions;
  if (state_[i] != PointState::Done) return false;
  nlohmann::json summary;
  try {
    summary = read_point_summary(folder / "summary.json");
  } catch (const std::exception&) {
    state_[i] = PointState::Fresh;  // an unreadable summary.json: run the point anew
    return false;
  }
  {
    std::lock_guard lock(mutex_);
    records_[i].status = PointStatus::Done;
    records_[i].summary = std::move(summary);
  }
  if (!needs_confirmation(i) ||
      !std::filesystem::is_regular_file(folder / kColdStart / "summary.json"))
    return true;
  try {
    // No search here: a cold start without its recorded choice (run under
    // another rule) is left to confirm_jam, which says what is wrong.
    ColdStartChoice cold = cold_choice(i, false);
    if (!cold.unchosen && inspect_point_folder(cold_point(p, std::move(cold.config)),
                                               folder / kColdStart) == PointState::Done) {
      auto cold_summary = read_point_summary(folder / kColdStart / "summary.json");
      std::lock_guard lock(mutex_);
      records_[i].cold_start = std::move(cold_summary);
      records_[i].cold_start_choice = std::move(cold.record);
    }
  } catch (const std::exception&) {
    // unreadable, or its choice cannot be made again: the confirmation runs again
  }
  return true;
}

std::vector<WorkUnit> SweepWork::work_units() const {
  std::vector<WorkUnit> units;
  for (const auto& chain : continuation_chains(plan_)) {
    WorkUnit unit;
    for (std::size_t i : chain)
      if (state_[i] != PointState::Done || needs_confirmation(i) || needs_extension(i))
        unit.push_back(i);
    if (!unit.empty()) units.push_back(std::move(unit));
  }
  return units;
}

void SweepWork::run_unit(const WorkUnit& unit, bool inspect_first) {
  if (inspect_first) {
    // The unit's points and those they continue from, back to the chain's
    // cold start: no other rank touches them while this one holds the chain.
    std::set<std::size_t> chain;
    for (std::size_t i : unit)
      for (std::optional<std::size_t> k = i; k; k = plan_.points[*k].continues_from)
        chain.insert(*k);
    try {
      for (std::size_t i : chain) load_point(i);  // in index order: predecessors first
    } catch (const std::exception& e) {
      // Rank 0 compared these folders before handing the unit out: only a
      // folder changed meanwhile, or one this rank cannot read, gets here.
      for (std::size_t i : unit) finish(i, PointStatus::Failed, one_line(e.what()));
      return;
    }
  }
  for (std::size_t i : unit) run_point(i);
}

// The cold start of continued point i's jam (cold_start_choice.hpp). The
// matched rule reads the ramp's records, copied under the lock; a "bulk"
// choice builds packings, without it, and only when `search`.
ColdStartChoice SweepWork::cold_choice(std::size_t i, bool search) const {
  std::vector<PointRecord> records;
  if (plan_.settings.cold_start_phi == SweepSettings::ColdStartPhi::Matched) {
    std::lock_guard lock(mutex_);
    records = records_;
  }
  return choose_cold_start(plan_, i, records, options_.out, search, &halt_);
}

// A continued point that jammed, whose cold start has not run yet.
bool SweepWork::needs_confirmation(std::size_t i) const {
  std::lock_guard lock(mutex_);
  return plan_.settings.confirm_jams && is_continued(plan_.points[i]) && jammed(records_[i]) &&
         !records_[i].cold_start.is_object();
}

// The jam of continued point i, run again from a new packing in its folder's
// cold-start/ (resumable like a point): a ramp's jam is reported with whether
// the same stress jams a cold start too.
void SweepWork::confirm_jam(std::size_t i) {
  if (halt_.load()) return;
  const auto folder = options_.out / plan_.points[i].folder / kColdStart;
  try {
    ColdStartChoice choice = cold_choice(i, true);
    if (halt_.load()) return;  // stopped during the search: its choice is not kept
    const SweepPoint cold = cold_point(plan_.points[i], std::move(choice.config));
    const PointState state = inspect_point_folder(cold, folder);
    if (choice.fresh) {
      std::filesystem::create_directories(folder);
      write_file_atomically(folder / kPhiChoiceFile, choice.record.dump(2) + "\n");
      if (!choice.record.value("within_tolerance", false)) {
        std::lock_guard lock(mutex_);
        events_.notes.push_back(fmt::format(
            "dilatant: {}: no packing of the cold start begins within {} of the jam's bulk "
            "fraction {:.4f}; the closest, {:.4f}, is used ({}/{})",
            plan_.points[i].folder, kBulkTolerance, choice.record["target_phi_bulk"].get<double>(),
            choice.record["phi_bulk_start"].get<double>(), kColdStart, kPhiChoiceFile));
        changed_.notify_all();
      }
    }
    nlohmann::json summary;
    if (state != PointState::Done) {
      CellRunOptions o;
      o.run.out_dir = folder;
      o.run.quiet = true;
      o.resume = state == PointState::Resumable;
      o.stop_requested = &halt_;
      CellOutcome outcome = run_shear_cell(cold.config, o);
      if (outcome.interrupted) return;
      summary = std::move(outcome.summary);
    }
    // A run finished before (by an earlier sweep) is read from its folder.
    if (!summary.is_object()) summary = read_point_summary(folder / "summary.json");
    std::lock_guard lock(mutex_);
    records_[i].cold_start = std::move(summary);
    records_[i].cold_start_choice = std::move(choice.record);
    changed(i, true);
  } catch (const std::exception& e) {
    if (halt_.load()) return;  // stopped: it runs again on the next invocation
    std::lock_guard lock(mutex_);
    events_.notes.push_back(
        fmt::format("dilatant: the cold start confirming the jam of {} failed: {}",
                    plan_.points[i].folder, one_line(e.what())));
    changed_.notify_all();
  }
}

void SweepWork::run_point(std::size_t i) {
  if (halt_.load()) return;
  const SweepPoint& p = plan_.points[i];
  const auto folder = options_.out / p.folder;
  if (state_[i] == PointState::Done) {  // in the unit to run on, or for its jam's cold start
    if (needs_extension(i)) {
      nlohmann::json summary;
      {
        std::lock_guard lock(mutex_);
        summary = records_[i].summary;
        records_[i].status = PointStatus::Running;
        changed(i, false);
      }
      try {
        if (!finish_run(i, std::move(summary))) return;
      } catch (const std::exception& e) {
        finish(i, PointStatus::Failed, one_line(e.what()));
        return;
      }
    }
    if (needs_confirmation(i)) confirm_jam(i);
    return;
  }
  std::filesystem::path start_from;
  if (p.continues_from) {
    const SweepPoint& before = plan_.points[*p.continues_from];
    const PointRecord previous = record(before.index);
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
  } else if (p.refines) {
    RefinedStart start = refined_start(*p.refines, plan_.settings.stop_at_jam);
    if (start.verdict == RefinedStart::Verdict::Wait) {
      add_note(fmt::format("dilatant: {} {}", p.folder, start.why));
      return;  // stays pending
    }
    if (start.verdict != RefinedStart::Verdict::Run) {
      finish(
          i,
          start.verdict == RefinedStart::Verdict::Skip ? PointStatus::Skipped : PointStatus::Failed,
          start.why);
      return;
    }
    start_from = std::move(start.checkpoint);
  }
  {
    std::lock_guard lock(mutex_);
    records_[i].status = PointStatus::Running;
    changed(i, false);  // "running" is "pending" in the table: no rewrite
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
    const Config config = config_of(i);
    CellOutcome outcome = run_shear_cell(config, o);
    if (o.resume && !outcome.interrupted &&
        !std::filesystem::is_regular_file(folder / "summary.json")) {
      // The checkpoint is the final state of a run whose result files are
      // gone (summary.json deleted to redo the point): run it anew.
      o.resume = false;
      o.start_from = start_from;
      outcome = run_shear_cell(config, o);
    }
    if (outcome.interrupted) {
      finish(i, PointStatus::Pending, "");
      return;
    }
    if (!std::filesystem::is_regular_file(folder / "summary.json"))
      throw std::runtime_error("the run ended without writing summary.json");
    // The table takes the summary the run wrote, in memory; only a run that
    // had finished before this sweep (resumed with nothing left) is read back.
    nlohmann::json summary = outcome.summary.is_object()
                                 ? std::move(outcome.summary)
                                 : read_point_summary(folder / "summary.json");
    if (!finish_run(i, std::move(summary))) return;
  } catch (const std::exception& e) {
    finish(i, PointStatus::Failed, one_line(e.what()));
    return;
  }
  if (needs_confirmation(i)) confirm_jam(i);
}

Config SweepWork::config_of(std::size_t i) const {
  return extended_config(plan_.points[i].config, extensions_[i]);
}

// Whether a point continues from point i's final state already: then that
// state is no longer point i's to change.
bool SweepWork::successor_started(std::size_t i) const {
  for (const SweepPoint& q : plan_.points)
    if (q.continues_from == i &&
        std::filesystem::is_regular_file(options_.out / q.folder / "config.toml"))
      return true;
  return false;
}

bool SweepWork::needs_extension(std::size_t i) const {
  const auto cap = plan_.settings.extend_unsteady_to;
  if (!cap || state_[i] != PointState::Done || successor_started(i)) return false;
  const PointRecord r = record(i);
  return r.status == PointStatus::Done && sweep::needs_extension(r.summary, config_of(i), *cap);
}

bool SweepWork::finish_run(std::size_t i, nlohmann::json summary) {
  const auto cap = plan_.settings.extend_unsteady_to;
  const SweepPoint& p = plan_.points[i];
  if (cap && !successor_started(i) &&
      !run_on_while_unsteady({.folder = options_.out / p.folder,
                              .name = p.folder,
                              .planned = p.config,
                              .cap = *cap,
                              .halt = &halt_,
                              .progress = &fraction_[i],
                              .note = [this](std::string line) { add_note(std::move(line)); }},
                             extensions_[i], summary)) {
    state_[i] = PointState::Resumable;
    finish(i, PointStatus::Pending, "");
    return false;
  }
  finish(i, PointStatus::Done, "", std::move(summary));
  return true;
}

void SweepWork::finish(std::size_t i, PointStatus status, const std::string& error,
                       nlohmann::json summary) {
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
    events_.notes.push_back(
        fmt::format("dilatant: point {} failed: {}", plan_.points[i].folder, error));
  changed(i, true);
}

void SweepWork::changed(std::size_t i, bool table_changed) {
  events_.table_changed = events_.table_changed || table_changed;
  events_.changed_points.push_back(i);
  changed_.notify_all();
}

}  // namespace dilatant::sweep
