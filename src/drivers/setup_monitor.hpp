#pragma once
// A cell's set-up can take minutes (the packing growth of a large cell:
// drivers/packing_growth.hpp): the loops that make it call setup_pass() between
// their passes, which reports the fraction done and abandons the set-up when a
// stop was requested (Ctrl-C), so that a mistyped size never leaves a run that
// prints nothing and cannot be stopped (issue 31 item 2).
//
//     ScopedSetupMonitor monitor({.stop = &flag, .progress = print_fraction});
//     ShearCell cell(config);       // throws SetupInterrupted once flag is set
//
// The monitor belongs to the thread that installs it (a sweep's workers each
// set up their own points); without one, setup_pass() does nothing.
#include <atomic>
#include <functional>
#include <stdexcept>
#include <string_view>

namespace dilatant {

struct SetupMonitor {
  const std::atomic<bool>* stop = nullptr;  // set: the set-up throws SetupInterrupted
  std::function<void(std::string_view stage, double fraction)> progress;  // may be empty
};

// The set-up was abandoned at a stop request: nothing was run or written.
class SetupInterrupted : public std::runtime_error {
 public:
  SetupInterrupted() : std::runtime_error("interrupted during the set-up; nothing was written") {}
};

// Installs `monitor` for set-ups on this thread while it lives (the previous
// one, if any, is restored after).
class ScopedSetupMonitor {
 public:
  explicit ScopedSetupMonitor(SetupMonitor monitor);
  ~ScopedSetupMonitor();
  ScopedSetupMonitor(const ScopedSetupMonitor&) = delete;
  ScopedSetupMonitor& operator=(const ScopedSetupMonitor&) = delete;

 private:
  SetupMonitor monitor_;
  const SetupMonitor* previous_;
};

// Between two passes of a set-up loop: reports `fraction` (0-1) of `stage`
// done, then throws SetupInterrupted if a stop was requested.
void setup_pass(std::string_view stage, double fraction);

}  // namespace dilatant
