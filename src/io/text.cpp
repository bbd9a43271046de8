#include "io/text.hpp"

#include <fmt/format.h>

#include <fstream>
#include <sstream>

#include "io/input_error.hpp"

namespace dilatant {

std::string read_input_file(const std::filesystem::path& file, std::string_view what) {
  std::ifstream in(file, std::ios::binary);
  if (!in || std::filesystem::is_directory(file))
    throw InputError(
        fmt::format("{}: cannot read the {} ({})", file.string(), what,
                    std::filesystem::exists(file) ? "not a readable file" : "no such file"));
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace dilatant
