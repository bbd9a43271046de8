#include "app/stop_request.hpp"

#include <csignal>

namespace dilatant {

namespace {

// A lock-free atomic store is what a signal handler may do (std::signal's rules).
std::atomic<bool> g_stop_requested{false};
static_assert(std::atomic<bool>::is_always_lock_free);

extern "C" void request_stop(int) { g_stop_requested.store(true); }

}  // namespace

const std::atomic<bool>* stop_on_interrupt() {
  std::signal(SIGINT, request_stop);
  std::signal(SIGTERM, request_stop);
  return &g_stop_requested;
}

}  // namespace dilatant
