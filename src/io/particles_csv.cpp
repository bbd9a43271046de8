// Reading a scene's particles from CSV; see particles_csv.hpp for the format.
#include "io/particles_csv.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <fstream>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>

#include "io/input_error.hpp"
#include "io/table_rows.hpp"
#include "io/text.hpp"

namespace dilatant {
namespace {

using namespace std::string_view_literals;

// Column order here fixes the numbering used by `assign` below.
constexpr std::array kColumns = {"id"sv, "x"sv,  "y"sv,  "z"sv,  "r"sv,  "vx"sv,
                                 "vy"sv, "vz"sv, "wx"sv, "wy"sv, "wz"sv, "fixed"sv};
constexpr std::size_t kRequired = 5;  // id, x, y, z, r

std::vector<std::string_view> split(std::string_view line) {
  std::vector<std::string_view> fields;
  std::size_t start = 0;
  while (true) {
    const auto comma = line.find(',', start);
    fields.push_back(trim(line.substr(start, comma - start)));
    if (comma == std::string_view::npos) return fields;
    start = comma + 1;
  }
}

class Reader {
 public:
  explicit Reader(std::string file) : file_(std::move(file)) {}

  [[noreturn]] void fail(std::string_view what) const {
    throw InputError(fmt::format("{}:{}: {}", file_, line_, what));
  }
  void set_line(std::size_t line) { line_ = line; }

  // Maps each header field to its column in kColumns.
  std::vector<std::size_t> header(std::string_view line) const {
    std::vector<std::size_t> columns;
    for (const auto name : split(line)) {
      const auto it = std::find(kColumns.begin(), kColumns.end(), name);
      if (name.empty()) fail("header has an empty column name");
      if (it == kColumns.end())
        fail(fmt::format("unknown column '{}' (known: id,x,y,z,r,vx,vy,vz,wx,wy,wz,fixed)", name));
      const auto column = static_cast<std::size_t>(it - kColumns.begin());
      if (std::find(columns.begin(), columns.end(), column) != columns.end())
        fail(fmt::format("duplicate column '{}'", name));
      columns.push_back(column);
    }
    for (std::size_t c = 0; c < kRequired; ++c)
      if (std::find(columns.begin(), columns.end(), c) == columns.end())
        fail(fmt::format("missing required column '{}' (required: id,x,y,z,r)", kColumns[c]));
    return columns;
  }

  ParticleRecord row(std::string_view line, const std::vector<std::size_t>& columns) const {
    const auto fields = split(line);
    check_field_count(file_, line_, fields.size(), columns.size());
    ParticleRecord p;
    for (std::size_t i = 0; i < fields.size(); ++i) assign(p, columns[i], fields[i]);
    if (!(p.radius > 0.0)) fail(fmt::format("column 'r': radius must be > 0, got {}", p.radius));
    return p;
  }

 private:
  void assign(ParticleRecord& p, std::size_t column, std::string_view text) const {
    const auto name = kColumns[column];
    if (column == 0) {
      p.id = integer(name, text);
    } else if (column == 11) {
      p.fixed = boolean(name, text);
    } else if (column == 4) {
      p.radius = number(name, text);
    } else {
      // x,y,z = 1..3; vx,vy,vz = 5..7; wx,wy,wz = 8..10
      const auto k = static_cast<Eigen::Index>(column < 4 ? column - 1 : (column - 5) % 3);
      Vec3& v = column < 4 ? p.position : column < 8 ? p.velocity : p.angular_velocity;
      v[k] = number(name, text);
    }
  }

  double number(std::string_view name, std::string_view text) const {
    if (text.empty()) fail(fmt::format("column '{}': empty field", name));
    const auto digits = text.front() == '+' ? text.substr(1) : text;
    double v = 0.0;
    const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), v);
    if (ec != std::errc() || end != digits.data() + digits.size())
      fail(fmt::format("column '{}': '{}' is not a number", name, text));
    if (!std::isfinite(v)) fail(fmt::format("column '{}': '{}' is not finite", name, text));
    return v;
  }

  std::int64_t integer(std::string_view name, std::string_view text) const {
    if (text.empty()) fail(fmt::format("column '{}': empty field", name));
    const auto digits = text.front() == '+' ? text.substr(1) : text;
    std::int64_t v = 0;
    const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), v);
    if (ec != std::errc() || end != digits.data() + digits.size())
      fail(fmt::format("column '{}': '{}' is not an integer", name, text));
    return v;
  }

  bool boolean(std::string_view name, std::string_view text) const {
    std::string lower(text);
    std::transform(lower.begin(), lower.end(), lower.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (lower == "1" || lower == "true") return true;
    if (lower == "0" || lower == "false") return false;
    fail(fmt::format("column '{}': '{}' is not 0, 1, true or false", name, text));
  }

  std::string file_;
  std::size_t line_ = 0;
};

}  // namespace

std::vector<ParticleRecord> read_particles_csv(const std::filesystem::path& file) {
  const auto name = file.string();
  std::ifstream in(file, std::ios::binary);
  if (!in || std::filesystem::is_directory(file))
    throw InputError(
        fmt::format("{}: cannot read the particle file ({})", name,
                    std::filesystem::exists(file) ? "not a readable file" : "no such file"));
  Reader reader(name);
  std::optional<std::vector<std::size_t>> columns;
  std::vector<ParticleRecord> particles;
  std::unordered_map<std::int64_t, std::size_t> line_of_id;  // to name both duplicates
  std::string text;
  for (std::size_t line = 1; std::getline(in, text); ++line) {
    const auto content = trim(text);
    if (content.empty()) continue;
    reader.set_line(line);
    if (!columns) {
      columns = reader.header(content);
      continue;
    }
    const auto p = reader.row(content, *columns);
    const auto [it, inserted] = line_of_id.emplace(p.id, line);
    if (!inserted) reader.fail(fmt::format("duplicate id {} (first on line {})", p.id, it->second));
    particles.push_back(p);
  }
  if (!columns)
    throw InputError(
        fmt::format("{}: empty file (expected a header row such as id,x,y,z,r)", name));
  if (particles.empty())
    throw InputError(fmt::format("{}: no particles (only a header row)", name));
  return particles;
}

}  // namespace dilatant
