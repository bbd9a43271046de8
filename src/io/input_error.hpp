#pragma once
// The one exception type for bad user input (config files, --set overrides, CSV
// inputs). Its message is a single line that names the file (and line when
// known), the key or column, and what is wrong, e.g.
//     scene.toml:7: friction.mu0 = -0.1: must be >= 0
//     particles.csv:4: column 'r': 'abc' is not a number
// so the CLI can print it as is and exit with code 2 (README "Using it"). Anything else
// thrown by the library is a failure of the program, not of the input (exit 1).
#include <stdexcept>
#include <string>

namespace dilatant {

struct InputError : std::runtime_error {
  explicit InputError(const std::string& message) : std::runtime_error(message) {}
};

}  // namespace dilatant
