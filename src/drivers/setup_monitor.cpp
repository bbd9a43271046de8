#include "drivers/setup_monitor.hpp"

namespace dilatant {
namespace {

thread_local const SetupMonitor* t_monitor = nullptr;

}  // namespace

ScopedSetupMonitor::ScopedSetupMonitor(SetupMonitor monitor)
    : monitor_(std::move(monitor)), previous_(t_monitor) {
  t_monitor = &monitor_;
}

ScopedSetupMonitor::~ScopedSetupMonitor() { t_monitor = previous_; }

void setup_pass(std::string_view stage, double fraction) {
  const SetupMonitor* m = t_monitor;
  if (m == nullptr) return;
  if (m->progress) m->progress(stage, fraction);
  if (m->stop != nullptr && m->stop->load()) throw SetupInterrupted();
}

}  // namespace dilatant
