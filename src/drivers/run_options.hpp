#pragma once
// What every run of the CLI shares, whatever it simulates: where its results go
// and whether it talks on the terminal.
#include <filesystem>

namespace dilatant {

struct RunOptions {
  std::filesystem::path out_dir;
  bool quiet = false;
};

}  // namespace dilatant
