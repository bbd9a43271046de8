#include "sweep/sweep_watch.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <ctime>
#include <iostream>

#include "io/atomic_file.hpp"

namespace dilatant::sweep {
namespace {

constexpr auto kFileInterval = std::chrono::seconds(10);

std::string utc_now() {
  const std::time_t now = std::time(nullptr);
  std::tm utc{};
  gmtime_r(&now, &utc);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", &utc);
  return text;
}

std::string duration_text(double seconds) {
  const auto s = static_cast<long>(seconds + 0.5);
  if (s < 60) return fmt::format("{}s", s);
  if (s < 3600) return fmt::format("{}m{:02}s", s / 60, s % 60);
  return fmt::format("{}h{:02}m", s / 3600, (s % 3600) / 60);
}

}  // namespace

SweepWatch::SweepWatch(SweepWork& work, const SweepRunOptions& options)
    : work_(work),
      options_(options),
      baseline_(work.plan().points.size(), -1.0),
      start_(Clock::now()),
      last_line_(Clock::now() - std::chrono::seconds(10)),
      last_file_(Clock::now() - std::chrono::seconds(60)) {}

void SweepWatch::tick(const SweepEvents& events) {
  if (options_.stop != nullptr && options_.stop->load()) work_.halt();
  std::vector<std::string> notes = events.notes;
  if (events.table_changed) {
    try {
      work_.write_table();
    } catch (const std::exception& e) {
      notes.push_back(fmt::format("dilatant: cannot write flowcurves.csv: {}", e.what()));
      work_.halt();
    }
  }
  for (const auto& note : notes)
    if (options_.report_failures || options_.show_progress)
      std::cerr << (progress_shown_ ? "\r\033[K" : "") << note << "\n";
  if (options_.progress != nullptr) options_.progress->store(fraction_done());
  if (Clock::now() - last_file_ >= kFileInterval) write_progress_file(false);
  if (options_.show_progress && Clock::now() - last_line_ >= std::chrono::seconds(1)) {
    std::cerr << "\r\033[K" << progress_line() << std::flush;
    progress_shown_ = true;
    last_line_ = Clock::now();
  }
}

void SweepWatch::finish() {
  if (options_.progress != nullptr) options_.progress->store(fraction_done());
  write_progress_file(true);
  if (progress_shown_) std::cerr << "\n";
}

double SweepWatch::fraction_done() const {
  const std::vector<PointStatus> status = work_.statuses();
  if (status.empty()) return 1.0;
  double done = 0.0;
  for (std::size_t i = 0; i < status.size(); ++i) {
    const bool running = status[i] == PointStatus::Pending || status[i] == PointStatus::Running;
    done += running ? std::clamp(work_.fraction(i), 0.0, 1.0) : 1.0;
  }
  return done / static_cast<double>(status.size());
}

// The time left is extrapolated from the strain the running points made since
// this invocation started.
std::string SweepWatch::progress_line() {
  const std::vector<PointStatus> status = work_.statuses();
  std::size_t done = 0, running = 0, failed = 0;
  double progressed = 0.0, remaining = 0.0;
  for (std::size_t i = 0; i < status.size(); ++i) {
    const PointStatus s = status[i];
    done += s == PointStatus::Done;
    running += s == PointStatus::Running;
    failed += s == PointStatus::Failed;
    const double f = work_.fraction(i);
    if (f >= 0.0 && baseline_[i] < 0.0) baseline_[i] = f;  // where this invocation took it up
    if (baseline_[i] >= 0.0) progressed += std::max(0.0, f - baseline_[i]);
    if (s == PointStatus::Pending || s == PointStatus::Running) remaining += 1.0 - std::max(0.0, f);
  }
  const double elapsed = std::chrono::duration<double>(Clock::now() - start_).count();
  const std::string left =
      progressed > 0.0 ? "about " + duration_text(elapsed * remaining / progressed) : "unknown";
  return fmt::format("sweep: {}/{} done, {} running, {} failed; {} elapsed, {} left", done,
                     status.size(), running, failed, duration_text(elapsed),
                     remaining > 0.0 ? left : "nothing");
}

void SweepWatch::write_progress_file(bool ended) {
  last_file_ = Clock::now();
  if (progress_file_failed_) return;
  std::string text =
      fmt::format("# dilatant sweep: progress at {} ({})\n{}\n", utc_now(),
                  ended ? "this invocation has ended" : "rewritten every 10 s", progress_line());
  for (const auto& [i, fraction] : work_.running_fractions())
    text += fmt::format("running: {} {:.0f}%\n", work_.plan().points[i].folder,
                        100.0 * std::clamp(fraction, 0.0, 1.0));
  try {
    write_file_atomically(options_.out / "progress.txt", text);
  } catch (const std::exception& e) {
    // The table is what a sweep must keep; a progress file it cannot write is
    // said once and given up.
    std::cerr << (progress_shown_ ? "\r\033[K" : "")
              << fmt::format("dilatant: cannot write progress.txt: {}\n", e.what());
    progress_file_failed_ = true;
  }
}

}  // namespace dilatant::sweep
