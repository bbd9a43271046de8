// Typed reads from the TOML tree, with one-line error messages that name the
// file, line and dotted key (see config_detail.hpp).
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <sstream>

#include "io/config_detail.hpp"
#include "io/input_error.hpp"
#include "io/text.hpp"

namespace dilatant::config_detail {
namespace {

constexpr std::array kPlaneKeys = {std::string_view("point"), std::string_view("normal")};

}  // namespace

bool contains(std::span<const std::string_view> keys, std::string_view key) {
  return std::find(keys.begin(), keys.end(), key) != keys.end();
}

std::string join(std::span<const std::string_view> keys) {
  std::string out;
  for (auto k : keys) out += (out.empty() ? "" : ", ") + std::string(k);
  return out;
}

std::string_view type_name(const toml::node& n) {
  switch (n.type()) {
    case toml::node_type::table:
      return "table";
    case toml::node_type::array:
      return "array";
    case toml::node_type::string:
      return "string";
    case toml::node_type::integer:
      return "integer";
    case toml::node_type::floating_point:
      return "float";
    case toml::node_type::boolean:
      return "boolean";
    case toml::node_type::date:
      return "date";
    case toml::node_type::time:
      return "time";
    case toml::node_type::date_time:
      return "date-time";
    default:
      return "nothing";
  }
}

std::string show(const toml::node& n) {
  if (n.is_table()) return "{...}";
  std::ostringstream os;
  n.visit([&](const auto& v) { os << v; });
  auto text = std::move(os).str();
  std::replace(text.begin(), text.end(), '\n', ' ');  // messages are one line
  return text;
}
std::string show(double v) { return fmt::format("{}", v); }
std::string show(const Vec3& v) { return fmt::format("[{}, {}, {}]", v.x(), v.y(), v.z()); }
std::string show(const std::array<bool, 3>& v) {
  return fmt::format("[{}, {}, {}]", v[0], v[1], v[2]);
}
std::string show(std::int64_t v) { return fmt::format("{}", v); }
std::string show(const std::string& v) { return fmt::format("\"{}\"", v); }

std::string where(const std::string& source, const toml::node* n, std::string_view key) {
  if (n == nullptr) return fmt::format("{}: {}", source, key);
  const auto& src = n->source();
  if (src.begin.line == 0 || (src.path && *src.path == kOverrideSource))
    return fmt::format("--set {}", key);
  return fmt::format("{}:{}: {}", source, n->source().begin.line, key);
}

Section::Section(const std::string& source, const toml::node* table, std::string path)
    : source_(source), table_(table ? table->as_table() : nullptr), path_(std::move(path)) {}

const toml::node* Section::find(std::string_view key) const {
  return table_ ? table_->get(key) : nullptr;
}

const toml::node& Section::require(std::string_view key, std::string_view why) const {
  if (const auto* n = find(key)) return *n;
  // Located at the table's header (or the override that made it).
  throw InputError(fmt::format("{} is missing ({})", where(source_, table_, name(key)), why));
}

void Section::fail(std::string_view key, const std::string& value, std::string_view what) const {
  const auto* n = find(key);
  throw InputError(fmt::format("{} = {}{}: {}", where(source_, n, name(key)), value,
                               n ? "" : " (default)", what));
}

void Section::type_error(const toml::node& n, std::string_view name,
                         std::string_view expected) const {
  throw InputError(fmt::format("{}: expected {}, got {} {}", where(source_, &n, name), expected,
                               type_name(n), show(n)));
}

double Section::to_number(const toml::node& n, std::string_view name) const {
  double v = 0.0;
  if (const auto* i = n.as_integer())
    v = static_cast<double>(i->get());
  else if (const auto* f = n.as_floating_point())
    v = f->get();
  else
    type_error(n, name, "a number");
  if (!std::isfinite(v))
    throw InputError(fmt::format("{} = {}: must be finite", where(source_, &n, name), show(n)));
  return v;
}

const toml::array& Section::to_array3(const toml::node& n, std::string_view name) const {
  const auto* a = n.as_array();
  if (a == nullptr) type_error(n, name, "an array of 3 elements");
  if (a->size() != 3)
    throw InputError(fmt::format("{} = {}: expected 3 elements, got {}", where(source_, &n, name),
                                 show(n), a->size()));
  return *a;
}

double Section::number(std::string_view key, double fallback) const {
  const auto* n = find(key);
  return n ? to_number(*n, name(key)) : fallback;
}

std::int64_t Section::integer(std::string_view key, std::int64_t fallback) const {
  const auto* n = find(key);
  if (n == nullptr) return fallback;
  if (const auto* i = n->as_integer()) return i->get();
  type_error(*n, name(key), "an integer");
}

std::string Section::string(std::string_view key, const std::string& fallback) const {
  const auto* n = find(key);
  if (n == nullptr) return fallback;
  if (const auto* s = n->as_string()) return s->get();
  type_error(*n, name(key), "a string");
}

bool Section::boolean(std::string_view key, bool fallback) const {
  const auto* n = find(key);
  if (n == nullptr) return fallback;
  if (const auto* b = n->as_boolean()) return b->get();
  type_error(*n, name(key), "a boolean (true or false)");
}

Vec3 Section::vec3(std::string_view key, const Vec3& fallback) const {
  const auto* n = find(key);
  if (n == nullptr) return fallback;
  const auto& a = to_array3(*n, name(key));
  Vec3 v;
  for (std::size_t i = 0; i < 3; ++i)
    v[static_cast<Eigen::Index>(i)] = to_number(*a.get(i), fmt::format("{}[{}]", name(key), i));
  return v;
}

std::array<bool, 3> Section::bool3(std::string_view key,
                                   const std::array<bool, 3>& fallback) const {
  const auto* n = find(key);
  if (n == nullptr) return fallback;
  const auto& a = to_array3(*n, name(key));
  std::array<bool, 3> v{};
  for (std::size_t i = 0; i < 3; ++i) {
    const auto* b = a.get(i)->as_boolean();
    if (b == nullptr) type_error(*a.get(i), fmt::format("{}[{}]", name(key), i), "a boolean");
    v[i] = b->get();
  }
  return v;
}

void Section::reject_unknown(std::span<const std::string_view> known) const {
  if (table_ == nullptr) return;
  for (const auto& [key, node] : *table_)
    if (!contains(known, key.str()))
      throw InputError(fmt::format("{}: unknown key{} (known in [{}]: {})",
                                   where(source_, &node, name(key.str())),
                                   did_you_mean(key.str(), known), path_, join(known)));
}

std::vector<PlaneConfig> read_planes(const Section& scene) {
  std::vector<PlaneConfig> planes;
  const auto* node = scene.find("planes");
  if (node == nullptr) return planes;
  const auto* array = node->as_array();
  if (array == nullptr || !(array->empty() || array->is_array_of_tables()))
    throw InputError(fmt::format("{}: expected an array of tables ([[scene.planes]])",
                                 where(scene.source(), node, "scene.planes")));
  for (std::size_t i = 0; i < array->size(); ++i) {
    const Section s(scene.source(), array->get(i), fmt::format("scene.planes[{}]", i));
    s.reject_unknown(kPlaneKeys);
    PlaneConfig p;
    s.require("point", "a plane needs a point and a normal");
    s.require("normal", "a plane needs a point and a normal");
    p.point = s.vec3("point", p.point);
    p.normal = s.vec3("normal", p.normal);
    check(s, "normal", p.normal, p.normal.norm() > 0.0, "must not be the zero vector");
    p.normal.normalize();
    planes.push_back(p);
  }
  return planes;
}

}  // namespace dilatant::config_detail
