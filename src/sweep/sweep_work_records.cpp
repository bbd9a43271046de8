// SweepWork's records and events as the watching thread and other ranks read
// them, and the table written from them (sweep_work.hpp).
#include "io/atomic_file.hpp"
#include "sweep/sweep_work.hpp"

namespace dilatant::sweep {

void SweepWork::worker_started() {
  std::lock_guard lock(mutex_);
  ++events_.active_workers;
}

void SweepWork::worker_ended() {
  std::lock_guard lock(mutex_);
  --events_.active_workers;
  changed_.notify_all();
}

SweepEvents SweepWork::wait_for_events(std::chrono::milliseconds timeout) {
  std::unique_lock lock(mutex_);
  changed_.wait_for(lock, timeout);
  SweepEvents out = std::move(events_);
  events_ = SweepEvents{};
  events_.active_workers = out.active_workers;
  return out;
}

PointRecord SweepWork::record(std::size_t i) const {
  std::lock_guard lock(mutex_);
  return records_[i];
}

void SweepWork::set_record(std::size_t i, PointRecord record) {
  std::lock_guard lock(mutex_);
  records_[i] = std::move(record);
  changed(i, records_[i].status != PointStatus::Running);
}

void SweepWork::add_note(std::string note) {
  std::lock_guard lock(mutex_);
  events_.notes.push_back(std::move(note));
  changed_.notify_all();
}

std::vector<PointStatus> SweepWork::statuses() const {
  std::vector<PointStatus> out;
  std::lock_guard lock(mutex_);
  for (const auto& r : records_) out.push_back(r.status);
  return out;
}

std::vector<std::pair<std::size_t, double>> SweepWork::running_fractions() const {
  std::vector<std::pair<std::size_t, double>> out;
  std::lock_guard lock(mutex_);
  for (std::size_t i = 0; i < records_.size(); ++i)
    if (records_[i].status == PointStatus::Running) out.emplace_back(i, fraction_[i].load());
  return out;
}

SweepOutcome SweepWork::outcome() const {
  SweepOutcome outcome;
  outcome.points = plan_.points.size();
  std::lock_guard lock(mutex_);
  for (const auto& r : records_) {
    outcome.done += r.status == PointStatus::Done;
    outcome.failed += r.status == PointStatus::Failed;
    outcome.pending += r.status == PointStatus::Pending || r.status == PointStatus::Running;
    outcome.above_jam += r.status == PointStatus::Skipped;
  }
  for (std::size_t i = 0; i < records_.size(); ++i) {
    const PointRecord& r = records_[i];
    const double f = r.status == PointStatus::Done && r.summary.is_object()
                         ? r.summary.value("frac_steps_unconverged", 0.0)
                         : 0.0;
    if (!(f > 0.0)) continue;
    ++outcome.unconverged_points;
    if (f > outcome.most_unconverged) {
      outcome.most_unconverged = f;
      outcome.most_unconverged_point = plan_.points[i].folder;
    }
  }
  return outcome;
}

void SweepWork::write_table() const {
  std::vector<PointRecord> records;
  {
    std::lock_guard lock(mutex_);
    records = records_;
  }
  write_file_atomically(options_.out / "flowcurves.csv",
                        flowcurves_csv(plan_, records, options_.out));
}

}  // namespace dilatant::sweep
