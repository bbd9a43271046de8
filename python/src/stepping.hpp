#pragma once
// Stepping an engine object from Python: each step with the GIL released, and
// Ctrl-C checked between steps, so that a long advance() stops with
// KeyboardInterrupt after the current step and leaves the object consistent.
#include <pybind11/pybind11.h>

#include <limits>
#include <optional>

#include "io/input_error.hpp"

namespace dilatant::python {

// The step budget of advance(amount=..., steps=...): `amount` (strain or time)
// is how far to go, `steps` how many steps at most; one of them is required.
inline long step_budget(const char* amount_name, std::optional<double> amount,
                        std::optional<long> steps) {
  if (!amount && !steps)
    throw InputError(std::string("advance: give ") + amount_name + "=... or steps=...");
  if (amount && !(*amount >= 0.0))
    throw InputError(std::string("advance: ") + amount_name + " must be >= 0");
  if (steps && *steps < 0) throw InputError("advance: steps must be >= 0");
  return steps ? *steps : std::numeric_limits<long>::max();
}

// Steps `object` while `more()` holds, at most `max_steps` times; returns the
// steps taken.
template <class Object, class More>
long step_while(Object& object, long max_steps, More more) {
  long taken = 0;
  while (taken < max_steps && more()) {
    {
      pybind11::gil_scoped_release release;
      object.step();
    }
    ++taken;
    if (PyErr_CheckSignals() != 0) throw pybind11::error_already_set();
  }
  return taken;
}

}  // namespace dilatant::python
