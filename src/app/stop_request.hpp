#pragma once
// Ctrl-C and `kill` during a long run: the handler only raises a flag; the run
// polls it between steps, finishes the step, writes a checkpoint and returns,
// so that `--resume` continues where it stopped (docs/reliability.md).
#include <atomic>

namespace dilatant {

// Installs the SIGINT and SIGTERM handlers and returns the flag they raise
// (one flag for the process: `run` and `sweep` both read it).
const std::atomic<bool>* stop_on_interrupt();

}  // namespace dilatant
