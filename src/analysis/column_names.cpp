#include "analysis/column_names.hpp"

#include <algorithm>
#include <array>
#include <utility>

#include "analysis/delimited_text.hpp"
#include "io/text.hpp"

namespace dilatant::analysis {
namespace {

using namespace std::string_view_literals;

struct Alias {
  std::string_view name;
  Quantity quantity;
};

// Lower-case names, spaces for '_', '-' and '.'; UTF-8 Greek symbols as written
// by rheometer software (γ̇ is gamma followed by a combining dot above).
constexpr std::array kAliases = {
    Alias{"shear rate", Quantity::ShearRate},
    Alias{"shearrate", Quantity::ShearRate},
    Alias{"rate", Quantity::ShearRate},
    Alias{"strain rate", Quantity::ShearRate},
    Alias{"gamma dot", Quantity::ShearRate},
    Alias{"gammadot", Quantity::ShearRate},
    Alias{"gdot", Quantity::ShearRate},
    Alias{"\xCE\xB3\xCC\x87", Quantity::ShearRate},  // γ̇
    Alias{"shear stress", Quantity::ShearStress},
    Alias{"shearstress", Quantity::ShearStress},
    Alias{"stress", Quantity::ShearStress},
    Alias{"tau", Quantity::ShearStress},
    Alias{"\xCF\x84", Quantity::ShearStress},  // τ
    Alias{"sigma", Quantity::ShearStress},
    Alias{"viscosity", Quantity::Viscosity},
    Alias{"apparent viscosity", Quantity::Viscosity},
    Alias{"shear viscosity", Quantity::Viscosity},
    Alias{"dynamic viscosity", Quantity::Viscosity},
    Alias{"visc", Quantity::Viscosity},
    Alias{"eta", Quantity::Viscosity},
    Alias{"\xCE\xB7", Quantity::Viscosity},  // η
    // German and French, as Anton Paar RheoCompass, Malvern rSpace and TA
    // TRIOS write them in those languages (issue 32): "Schubspannung",
    // "Scherrate", "Viskosität"; "Contrainte de Cisaillement", "Gradient de
    // Cisaillement", "Viscosité". Accented letters in UTF-8, and without
    // their accents as exports to ASCII write them.
    Alias{"schubspannung", Quantity::ShearStress},
    Alias{"scherspannung", Quantity::ShearStress},
    Alias{"contrainte de cisaillement", Quantity::ShearStress},
    Alias{"scherrate", Quantity::ShearRate},
    Alias{"schergeschwindigkeit", Quantity::ShearRate},
    Alias{"gradient de cisaillement", Quantity::ShearRate},
    Alias{"taux de cisaillement", Quantity::ShearRate},
    Alias{"vitesse de cisaillement", Quantity::ShearRate},
    Alias{"viskosit\xC3\xA4t", Quantity::Viscosity},  // Viskosität
    Alias{"viskositaet", Quantity::Viscosity},
    Alias{"viskositat", Quantity::Viscosity},
    Alias{"viscosit\xC3\xA9", Quantity::Viscosity},  // viscosité
    Alias{"viscosite", Quantity::Viscosity},
};

struct Unit {
  std::string_view text;  // normalised: see normalise_unit
  Quantity quantity;
  double factor;
};

constexpr std::array kUnits = {
    Unit{"1/s", Quantity::ShearRate, 1.0},       Unit{"s^-1", Quantity::ShearRate, 1.0},
    Unit{"s-1", Quantity::ShearRate, 1.0},       Unit{"/s", Quantity::ShearRate, 1.0},
    Unit{"1/sec", Quantity::ShearRate, 1.0},     Unit{"Pa", Quantity::ShearStress, 1.0},
    Unit{"pa", Quantity::ShearStress, 1.0},      Unit{"mPa", Quantity::ShearStress, 1e-3},
    Unit{"kPa", Quantity::ShearStress, 1e3},     Unit{"MPa", Quantity::ShearStress, 1e6},
    Unit{"dyn/cm2", Quantity::ShearStress, 0.1}, Unit{"dyn/cm^2", Quantity::ShearStress, 0.1},
    Unit{"dyn/cm", Quantity::ShearStress, 0.1},  // "dyn/cm²" once the ² is dropped
    Unit{"Pas", Quantity::Viscosity, 1.0},       Unit{"pas", Quantity::Viscosity, 1.0},
    Unit{"mPas", Quantity::Viscosity, 1e-3},     Unit{"kPas", Quantity::Viscosity, 1e3},
    Unit{"cP", Quantity::Viscosity, 1e-3},       Unit{"cp", Quantity::Viscosity, 1e-3},
    Unit{"P", Quantity::Viscosity, 0.1},
};

std::string normalise_name(std::string_view name) {
  std::string out;
  for (const char c : lower_case(name)) {
    const char d = c == '_' || c == '-' || c == '.' || c == '\t' ? ' ' : c;
    if (d == ' ' && (out.empty() || out.back() == ' ')) continue;
    out.push_back(d);
  }
  // A trailing ':' is kept: "Rate:" is a metadata key, not a column heading.
  while (!out.empty() && out.back() == ' ') out.pop_back();
  return out;
}

std::optional<Quantity> find_alias(std::string_view normalised) {
  for (const auto& a : kAliases)
    if (a.name == normalised) return a.quantity;
  return std::nullopt;
}

// A name, or a name followed by its symbol ("shear rate γ̇").
std::optional<Quantity> recognise(std::string_view name) {
  const std::string n = normalise_name(name);
  if (auto q = find_alias(n)) return q;
  const auto space = n.rfind(' ');
  if (space == std::string::npos) return std::nullopt;
  const auto symbol = find_alias(std::string_view(n).substr(space + 1));
  const auto rest = find_alias(std::string_view(n).substr(0, space));
  if (symbol && rest && *symbol == *rest) return rest;
  return std::nullopt;
}

// Superscripts as ASCII ("s⁻¹" and Malvern's "s-¹" become "s-1", "cm²"
// "cm2"), then keeps ASCII letters, digits, '/', '^' and '-': "mPa·s", "mPa.s",
// "mPa s" and "mPa*s" all become "mPas".
std::string normalise_unit(std::string_view unit) {
  std::string ascii(unit);
  for (const auto& [superscript, plain] :
       {std::pair{"\xE2\x81\xBB"sv, "-"sv}, std::pair{"\xC2\xB9"sv, "1"sv},
        std::pair{"\xC2\xB2"sv, "2"sv}, std::pair{"\xC2\xB3"sv, "3"sv}})
    for (auto at = ascii.find(superscript); at != std::string::npos; at = ascii.find(superscript))
      ascii.replace(at, superscript.size(), plain);
  std::string out;
  for (const char c : ascii) {
    const bool keep = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                      c == '/' || c == '^' || c == '-';
    if (keep) out.push_back(c);
  }
  return out;
}

// "name [unit]", "name (unit)", "name / unit", "name in unit".
std::pair<std::string_view, std::string_view> split_heading(std::string_view h) {
  for (const auto& [open, close] : {std::pair{'[', ']'}, std::pair{'(', ')'}}) {
    const auto at = h.find(open);
    if (at == std::string_view::npos) continue;
    const auto end = h.find(close, at);
    const auto inside = h.substr(at + 1, end == std::string_view::npos ? end : end - at - 1);
    // "Shear rate (γ̇)": a symbol in parentheses is part of the name.
    if (open == '(' && find_alias(normalise_name(inside))) return {h.substr(0, at), ""};
    return {h.substr(0, at), trim(inside)};
  }
  for (const auto sep : {" / "sv, " in "sv}) {
    const auto at = h.find(sep);
    if (at != std::string_view::npos) return {h.substr(0, at), trim(h.substr(at + sep.size()))};
  }
  return {h, ""};
}

// A parenthesised qualifier, not a unit: "Contrainte de Cisaillement (pour
// déformation sinusoïdale)" is RheoCompass's oscillation amplitude, "Stress
// (step)" TRIOS's stress of a step; either is another column than the
// quantity named. Qualifiers are words (two or more, one of them of 4 letters
// or more) or one of TRIOS's tags; a unit is one short token ("mPa·s", "Pa s",
// "1/s"), and an unknown one ("Poise") stays an error.
bool is_qualifier(std::string_view part) {
  const std::string p = lower_case(trim(part));
  for (const auto tag : {"step"sv, "cmd"sv, "raw"sv, "set"sv, "average"sv, "avg"sv, "mean"sv})
    if (p == tag) return true;
  std::size_t words = 0, longest = 0, run = 0;
  bool in_word = false;
  for (const char c : p + ' ') {
    // Accented letters (UTF-8 bytes >= 0x80) continue a word but do not
    // lengthen it: "cm²" is 2 letters, "déformation" 10.
    const bool ascii = c >= 'a' && c <= 'z';
    const bool letter = ascii || (static_cast<unsigned char>(c) & 0x80);
    if (ascii) ++run;
    if (letter && !in_word) ++words;
    if (!letter) {
      longest = std::max(longest, run);
      run = 0;
    }
    in_word = letter;
  }
  return words >= 2 && longest >= 4;
}

}  // namespace

std::string_view quantity_name(Quantity q) {
  switch (q) {
    case Quantity::ShearRate:
      return "shear rate";
    case Quantity::ShearStress:
      return "shear stress";
    case Quantity::Viscosity:
      return "viscosity";
  }
  return "";
}

Heading parse_heading(std::string_view heading) {
  const auto [name, unit] = split_heading(trim(heading));
  if (is_qualifier(unit)) return Heading{std::nullopt, std::string(unit)};
  return Heading{recognise(name), std::string(unit)};
}

bool names_step_column(std::string_view heading) {
  const std::string n = normalise_name(trim(heading));
  return n == "action name" || n == "step name" || n == "step" || n == "action";
}

std::string unit_of_units_field(std::string_view field) {
  std::string_view f = trim(field);
  if (f.size() >= 2 && (f.front() == '[' || f.front() == '(')) f = trim(f.substr(1, f.size() - 2));
  return std::string(f);
}

std::optional<double> si_factor(Quantity q, std::string_view unit) {
  if (trim(unit).empty()) return 1.0;
  const std::string u = normalise_unit(unit);
  for (const auto& known : kUnits)
    if (known.quantity == q && known.text == u) return known.factor;
  return std::nullopt;
}

std::string_view known_units(Quantity q) {
  switch (q) {
    case Quantity::ShearRate:
      return "1/s, s^-1, s-1, s\xE2\x81\xBB\xC2\xB9";
    case Quantity::ShearStress:
      return "Pa, mPa, kPa, MPa, dyn/cm2";
    case Quantity::Viscosity:
      return "Pa·s, mPa·s, kPa·s, cP, P";
  }
  return "";
}

}  // namespace dilatant::analysis
