#pragma once
// Builders for the entries of the table of configuration keys
// (io/config_keys.cpp, io/config_keys_sediment.cpp): a number with its range,
// an integer, a 3-vector, a word from a list. Each returns a ConfigKey whose
// read() range-checks the value and whose write() puts it back.
#include <fmt/format.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <utility>
#include <vector>

#include "io/config_keys.hpp"
#include "io/input_error.hpp"

namespace dilatant::config_key_builders {

using config_detail::Section;
constexpr double kInf = std::numeric_limits<double>::infinity();
// The HD friction 2 pi s ln(5/(6 pi s)) is positive only below this (docs/model.md "Friction").
constexpr double kSommerfeldMax = 5.0 / (6.0 * std::numbers::pi);

// Where each section's struct lives in a Config (cell, scene, sediment: the run mode).
template <class T>
using Get = T& (*)(Config&);
inline CellConfig& cell(Config& c) { return std::get<CellConfig>(c.mode); }
inline SceneConfig& scene(Config& c) { return std::get<SceneConfig>(c.mode); }
inline SedimentConfig& sediment(Config& c) { return std::get<SedimentConfig>(c.mode); }
inline FrictionConfig& friction(Config& c) { return c.friction; }
inline FluidConfig& fluid(Config& c) { return c.fluid; }
inline SolverConfig& solver(Config& c) { return c.solver; }
inline RunConfig& run(Config& c) { return c.run; }
// write() reads through the same accessors; they do not modify.
inline Config& mut(const Config& c) { return const_cast<Config&>(c); }

// An interval of accepted numbers and how a message states it.
struct Range {
  double lo = -kInf, hi = kInf;
  bool lo_closed = true, hi_closed = true;
  std::string_view hi_text = {};  // shown instead of hi ("5/(6 pi) ~ 0.2653")
  std::string_view note = {};     // appended to the message (" (0 = automatic)")

  bool contains(double v) const {
    return (lo_closed ? v >= lo : v > lo) && (hi_closed ? v <= hi : v < hi);
  }
  std::string text() const {
    const std::string h = hi_text.empty() ? fmt::format("{}", hi) : std::string(hi_text);
    if (lo == -kInf && hi == kInf) return "";
    if (hi == kInf) return fmt::format("{} {}", lo_closed ? ">=" : ">", lo);
    if (lo == -kInf) return fmt::format("{} {}", hi_closed ? "<=" : "<", h);
    return fmt::format("{}{}, {}{}", lo_closed ? "[" : "(", lo, h, hi_closed ? "]" : ")");
  }
  std::string message() const {
    const std::string t = text();
    return (hi == kInf || lo == -kInf ? "must be " + t : "must be in " + t) + std::string(note);
  }
};
inline Range at_least(double lo, std::string_view note = {}) {
  return {lo, kInf, true, true, {}, note};
}
inline Range above(double lo) { return {lo, kInf, false, true, {}, {}}; }
inline Range open(double lo, double hi) { return {lo, hi, false, false, {}, {}}; }

template <class S>
ConfigKey number(std::string_view section, std::string_view name, RunMode mode, Get<S> get,
                 double S::*member, Range range, std::string_view unit, std::string_view doc) {
  return ConfigKey{section,
                   name,
                   mode,
                   "float",
                   unit,
                   range.text(),
                   doc,
                   [=](const Section& s, Config& c, const std::filesystem::path&) {
                     double& v = get(c).*member;
                     v = s.number(name, v);
                     config_detail::check(s, name, v, range.contains(v), range.message());
                   },
                   [=](const Config& c, toml::table& t) { t.insert(name, get(mut(c)).*member); }};
}

template <class S>
ConfigKey integer(std::string_view section, std::string_view name, RunMode mode, Get<S> get,
                  int S::*member, std::int64_t lo, std::int64_t hi, std::string_view message,
                  std::string_view range_text, std::string_view doc) {
  return ConfigKey{section,
                   name,
                   mode,
                   "integer",
                   "",
                   std::string(range_text),
                   doc,
                   [=](const Section& s, Config& c, const std::filesystem::path&) {
                     int& v = get(c).*member;
                     const std::int64_t read = s.integer(name, v);
                     config_detail::check(s, name, read, read >= lo && read <= hi, message);
                     v = static_cast<int>(read);
                   },
                   [=](const Config& c, toml::table& t) { t.insert(name, get(mut(c)).*member); }};
}

template <class S>
ConfigKey boolean(std::string_view section, std::string_view name, RunMode mode, Get<S> get,
                  bool S::*member, std::string_view doc) {
  return ConfigKey{section,
                   name,
                   mode,
                   "boolean",
                   "",
                   "true or false",
                   doc,
                   [=](const Section& s, Config& c, const std::filesystem::path&) {
                     bool& v = get(c).*member;
                     v = s.boolean(name, v);
                   },
                   [=](const Config& c, toml::table& t) { t.insert(name, get(mut(c)).*member); }};
}

template <class S>
ConfigKey vec3(std::string_view section, std::string_view name, RunMode mode, Get<S> get,
               Vec3 S::*member, bool (*ok)(const Vec3&), std::string_view message,
               std::string_view range_text, std::string_view unit, std::string_view doc) {
  return ConfigKey{section,
                   name,
                   mode,
                   "[float, float, float]",
                   unit,
                   std::string(range_text),
                   doc,
                   [=](const Section& s, Config& c, const std::filesystem::path&) {
                     Vec3& v = get(c).*member;
                     v = s.vec3(name, v);
                     if (ok != nullptr) config_detail::check(s, name, v, ok(v), message);
                   },
                   [=](const Config& c, toml::table& t) {
                     const Vec3& v = get(mut(c)).*member;
                     t.insert(name, toml::array{v.x(), v.y(), v.z()});
                   }};
}

// A key that takes one of a few words, each standing for a value of `member`.
template <class S, class E>
ConfigKey choice(std::string_view section, std::string_view name, RunMode mode, Get<S> get,
                 E S::*member, std::vector<std::pair<std::string_view, E>> words,
                 std::string_view doc) {
  std::string range;
  for (std::size_t w = 0; w < words.size(); ++w) {
    if (w > 0) range += w + 1 == words.size() ? " or " : ", ";
    range += fmt::format("\"{}\"", words[w].first);
  }
  const auto word_of = [words](E value) {
    for (const auto& [word, v] : words)
      if (v == value) return std::string(word);
    return std::string(words.front().first);
  };
  return ConfigKey{
      section,
      name,
      mode,
      "string",
      "",
      range,
      doc,
      [=](const Section& s, Config& c, const std::filesystem::path&) {
        E& v = get(c).*member;
        const std::string read = s.string(name, word_of(v));
        bool known = false;
        for (const auto& [word, value] : words)
          if (read == word) v = value, known = true;
        config_detail::check(s, name, read, known, "must be " + range);
      },
      [=](const Config& c, toml::table& t) { t.insert(name, word_of(get(mut(c)).*member)); }};
}

}  // namespace dilatant::config_key_builders
