#pragma once
// Running library work from Python without blocking the interpreter.
//
// The work runs on a thread of its own with the GIL released; the calling
// (Python) thread wakes every `poll_interval`, takes the GIL and
//   - checks for signals: Ctrl-C raises KeyboardInterrupt in Python, so the
//     work is asked to stop (`stop`, the flag SIGINT sets in the CLI: the run
//     writes its checkpoint), waited for, and the KeyboardInterrupt re-raised;
//   - calls `poll` (e.g. a progress callback): false, or an exception, stops
//     the work the same way (the exception is re-raised after it stopped).
// The work's own exception (InputError, ...) is re-raised in the caller.
// Python's signal handlers run only in the main thread, so that is where
// Ctrl-C is seen; the worker never touches Python objects.
#include <pybind11/pybind11.h>

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <exception>
#include <functional>
#include <mutex>
#include <optional>
#include <thread>

namespace dilatant::python {

template <class Result, class Work>
Result run_interruptibly(Work work, std::atomic<bool>& stop, const std::function<bool()>& poll,
                         std::chrono::milliseconds poll_interval = std::chrono::milliseconds(100)) {
  std::mutex mutex;
  std::condition_variable finished;
  bool done = false;
  std::optional<Result> result;
  std::exception_ptr work_error;
  std::exception_ptr caller_error;
  std::thread worker;
  {
    pybind11::gil_scoped_release release;
    worker = std::thread([&] {
      try {
        result.emplace(work());
      } catch (...) {
        work_error = std::current_exception();
      }
      const std::lock_guard lock(mutex);
      done = true;
      finished.notify_all();
    });
  }
  for (;;) {
    {
      pybind11::gil_scoped_release release;
      std::unique_lock lock(mutex);
      if (finished.wait_for(lock, poll_interval, [&] { return done; })) break;
    }
    if (caller_error) continue;  // already stopping: wait for the work to end
    try {
      if (PyErr_CheckSignals() != 0) throw pybind11::error_already_set();
      if (!poll()) stop.store(true);
    } catch (...) {
      caller_error = std::current_exception();
      stop.store(true);
    }
  }
  {
    pybind11::gil_scoped_release release;
    worker.join();
  }
  if (caller_error) std::rethrow_exception(caller_error);
  if (work_error) std::rethrow_exception(work_error);
  return std::move(*result);
}

}  // namespace dilatant::python
