#include "sweep/point_folder.hpp"

#include <fmt/format.h>

#include <array>
#include <fstream>
#include <sstream>

#include "io/input_error.hpp"

namespace dilatant::sweep {
namespace {

std::string read_file(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

std::string without_comments(const std::string& text) {
  std::istringstream lines(text);
  std::string out;
  for (std::string line; std::getline(lines, line);)
    if (line.rfind('#', 0) != 0) out += line + "\n";
  return out;
}

// The first key whose value differs, as "key = a there, b in this sweep".
std::string first_difference(const std::string& there_text, const toml::table& here) {
  toml::table there;
  try {
    there = toml::parse(there_text);
  } catch (const toml::parse_error&) {
    return "its config.toml is not valid TOML";
  }
  const auto text = [](const toml::node* n) { return n ? toml_value_text(*n) : "(absent)"; };
  for (const toml::table* a : std::array<const toml::table*, 2>{&here, &there}) {
    for (const auto& [section, node] : *a) {
      const auto* table = node.as_table();
      if (table == nullptr) continue;
      for (const auto& [key, value] : *table) {
        const std::string dotted = fmt::format("{}.{}", section.str(), key.str());
        const toml::node* x = find_key(there, dotted);
        const toml::node* y = find_key(here, dotted);
        if (text(x) != text(y))
          return fmt::format("{} = {} there, {} in this sweep", dotted, text(x), text(y));
      }
    }
  }
  return "its config.toml differs";
}

}  // namespace

PointState inspect_point_folder(const SweepPoint& point, const std::filesystem::path& folder) {
  const auto config = folder / "config.toml";
  if (!std::filesystem::is_regular_file(config)) return PointState::Fresh;
  const std::string there = read_file(config);
  if (without_comments(there) != without_comments(resolved_toml(point.config)))
    throw InputError(fmt::format(
        "{}: holds a run of another configuration ({}): the sweep changed since it ran; use "
        "another --out, or delete that folder to run the point anew",
        folder.string(), first_difference(there, point.config.resolved)));
  if (std::filesystem::is_regular_file(folder / "summary.json")) return PointState::Done;
  if (std::filesystem::is_regular_file(folder / "checkpoint.bin")) return PointState::Resumable;
  return PointState::Fresh;
}

}  // namespace dilatant::sweep
