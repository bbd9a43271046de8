#pragma once
// Internals of the config loader, shared by config_*.cpp; not part of the API.
#include <toml++/toml.h>

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "geometry/vec3.hpp"
#include "io/config.hpp"

namespace dilatant::config_detail {

bool contains(std::span<const std::string_view> keys, std::string_view key);
std::string join(std::span<const std::string_view> keys);

// "integer", "string", ... as a user would say it.
std::string_view type_name(const toml::node& n);

// A value as one line of TOML-ish text, for messages.
std::string show(const toml::node& n);
std::string show(double v);
std::string show(const Vec3& v);
std::string show(const std::array<bool, 3>& v);
std::string show(std::int64_t v);
std::string show(const std::string& v);

// The source name given to override values when they are parsed.
inline constexpr std::string_view kOverrideSource = "--set";
// The source name of the built-in default cell (default_cell_config).
inline constexpr std::string_view kBuiltInSource = "<built-in>";

// Where a key is, for messages: "scene.toml:7: friction.mu0" for a key from the
// file, "--set friction.mu0" for one from an override (parsed with source
// kOverrideSource, or created without a source line), "scene.toml: friction.mu0"
// for an absent key.
std::string where(const std::string& source, const toml::node* n, std::string_view key);

// Typed, validated reads from one table (which may be absent: then every read
// returns its fallback). `path` is the table's dotted name, e.g. "friction".
class Section {
 public:
  Section(const std::string& source, const toml::node* table, std::string path);

  const toml::node* find(std::string_view key) const;
  const toml::table* find_table() const { return table_; }
  const toml::node& require(std::string_view key, std::string_view why) const;
  double number(std::string_view key, double fallback) const;
  std::int64_t integer(std::string_view key, std::int64_t fallback) const;
  std::string string(std::string_view key, const std::string& fallback) const;
  bool boolean(std::string_view key, bool fallback) const;
  Vec3 vec3(std::string_view key, const Vec3& fallback) const;
  std::array<bool, 3> bool3(std::string_view key, const std::array<bool, 3>& fallback) const;

  // Errors for keys not in `known`, naming them and the known ones.
  void reject_unknown(std::span<const std::string_view> known) const;

  std::string name(std::string_view key) const { return path_ + "." + std::string(key); }
  const std::string& source() const { return source_; }

  // "<where> = <value>: <what>"; the value shown is the effective one, marked
  // "(default)" when the key is absent.
  [[noreturn]] void fail(std::string_view key, const std::string& value,
                         std::string_view what) const;

 private:
  [[noreturn]] void type_error(const toml::node& n, std::string_view name,
                               std::string_view expected) const;
  double to_number(const toml::node& n, std::string_view name) const;
  const toml::array& to_array3(const toml::node& n, std::string_view name) const;

  const std::string& source_;
  const toml::table* table_;
  std::string path_;
};

// Range checks read best as `check(s, "mu0", f.mu0, f.mu0 >= 0, "must be >= 0")`.
template <class T>
void check(const Section& s, std::string_view key, const T& value, bool ok, std::string_view what) {
  if (!ok) s.fail(key, show(value), what);
}

// Applies "--set key=value" overrides to the parsed document.
void apply_overrides(toml::table& root, const std::vector<std::string>& overrides);

// The [[scene.planes]] tables of a [scene] section (each a point and a normal).
std::vector<PlaneConfig> read_planes(const Section& scene);

}  // namespace dilatant::config_detail
