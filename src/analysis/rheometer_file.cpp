#include "analysis/rheometer_file.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "analysis/column_names.hpp"
#include "analysis/delimited_text.hpp"
#include "analysis/rheometer_layout.hpp"
#include "io/input_error.hpp"

namespace dilatant::analysis {
namespace {

// The largest over the smallest of a quantity over a step's points.
double spread(const std::vector<FlowPoint>& points, double FlowPoint::*quantity) {
  const auto [lo, hi] =
      std::minmax_element(points.begin(), points.end(),
                          [&](const auto& a, const auto& b) { return a.*quantity < b.*quantity; });
  return (*hi).*quantity / (*lo).*quantity;
}

// A step at one rate or one stress (step_kind.hpp, kHoldSpread).
bool is_hold(const FlowCurveFile& c) {
  if (c.points.size() < 2) return false;
  return spread(c.points, &FlowPoint::shear_rate) < kHoldSpread ||
         spread(c.points, &FlowPoint::shear_stress) < kHoldSpread;
}

class FileReader {
 public:
  explicit FileReader(const std::filesystem::path& file)
      : source_(file.string()), lines_(read_text_lines(file)) {}

  [[noreturn]] void fail(std::size_t line, const std::string& what) const {
    throw InputError(fmt::format("{}:{}: {}", source_, line, what));
  }

  RheometerFile read() {
    if (std::all_of(lines_.begin(), lines_.end(), [](const auto& l) { return is_blank(l); }))
      fail(1, "empty file: expected a header naming shear rate, shear stress or viscosity");
    const RheometerLayout layout = find_rheometer_layout(source_, lines_);
    if (layout.steps.empty()) no_table(layout);
    const char mark = decimal_mark(lines_, layout);
    RheometerFile file{source_, {}};
    for (std::size_t k = 0; k < layout.steps.size(); ++k)
      file.steps.push_back(read_step(layout, k, mark));
    return file;
  }

 private:
  [[noreturn]] void no_table(const RheometerLayout& layout) const {
    if (const auto at = layout.single_heading_line) {
      for (const auto& f : split_fields(lines_[*at - 1], detect_separator(lines_[*at - 1])))
        if (const auto q = parse_heading(f).quantity)
          fail(*at, fmt::format("missing column: found only {} ('{}'); need two of shear rate, "
                                "shear stress, viscosity",
                                quantity_name(*q), f));
    }
    for (std::size_t i = 0; i < lines_.size(); ++i)
      if (parse_number(split_fields(lines_[i], detect_separator(lines_[i])).front()))
        fail(i + 1, "data before any header naming shear rate, shear stress or viscosity");
    fail(1, "no header line naming shear rate, shear stress or viscosity");
  }

  RheometerStep read_step(const RheometerLayout& layout, std::size_t k, char mark) {
    const RheometerStepRows& s = layout.steps[k];
    const RheometerTable& t = layout.tables[s.table];
    RheometerStep r;
    r.number = k + 1;
    r.name = s.name;
    r.first_line = s.first_line;
    r.rows = s.lines.size();
    r.last_line = s.lines.empty() ? t.units_line.value_or(t.header_line) : s.lines.back();
    const auto named = kind_from_name(s.name);
    if (named == StepKind::Oscillation || named == StepKind::Hold) {
      r.kind = *named;
      return r;
    }
    if (flow_headings(t.headings) < 2) {
      r.kind = has_oscillation_columns(t.headings) ? StepKind::Oscillation : StepKind::Other;
      return r;
    }
    r.kind = StepKind::FlowCurve;
    try {
      r.curve = read_flow_table(source_, lines_, t, s.lines, mark);
      if (is_hold(r.curve)) {
        r.kind = StepKind::Hold;
        return r;
      }
      drop_repeated_ramp_values(r.curve);
      const auto n = r.curve.points.size();
      if (n < kMinCurvePoints) {
        // Oscillation rows of a table that has every column (Malvern's)
        // leave the flow columns empty.
        if (!named && has_oscillation_columns(t.headings)) {
          r.kind = StepKind::Oscillation;
          return r;
        }
        r.problem = RheometerStep::Problem::TooFewPoints;
        r.why = fmt::format(
            "{}:{}: only {} data point{} {}; a flow curve needs at least {}{}", source_,
            n == 0 ? t.header_line : r.curve.points.back().line, n, n == 1 ? "" : "s",
            layout.steps.size() == 1 ? "after the header" : "in step " + r.label(), kMinCurvePoints,
            r.curve.dropped_rows == 0 ? "" : " (" + r.curve.dropped + ")");
        return r;
      }
      order_flow_curve(source_, r.curve);
    } catch (const InputError& e) {
      r.problem = RheometerStep::Problem::BadData;
      r.why = e.what();
    }
    return r;
  }

  std::string source_;
  std::vector<std::string> lines_;
};

[[noreturn]] void fail_choice(const StepChoice& c, const std::string& what) {
  throw InputError(c.origin.empty() ? what : c.origin + ": " + what);
}

std::string found_steps(const RheometerFile& file) {
  std::string out;
  for (const auto& s : file.steps) {
    out += fmt::format("{}step {} ({}, {} rows{})", out.empty() ? "" : "; ", s.label(),
                       step_kind_name(s.kind), s.rows,
                       s.problem == RheometerStep::Problem::TooFewPoints ? ", too few points" : "");
  }
  return out;
}

const RheometerStep& find_step(const RheometerFile& file, const StepChoice& choice) {
  const std::string see = fmt::format("dilatant analyze --list {} shows them", file.source);
  if (choice.number) {
    if (*choice.number < 1 || *choice.number > file.steps.size())
      fail_choice(choice,
                  fmt::format("step {}: {} has step{} 1 to {} ({})", *choice.number, file.source,
                              file.steps.size() == 1 ? "" : "s", file.steps.size(), see));
    return file.steps[*choice.number - 1];
  }
  std::vector<const RheometerStep*> named;
  for (const auto& s : file.steps)
    if (lower_case(s.name) == lower_case(*choice.name)) named.push_back(&s);
  if (named.empty())
    fail_choice(choice, fmt::format("step \"{}\": no step of {} has that name ({})", *choice.name,
                                    file.source, see));
  if (named.size() > 1) {
    std::string numbers;
    for (const auto* s : named)
      numbers += (numbers.empty() ? "" : ", ") + std::to_string(s->number);
    fail_choice(choice, fmt::format("step \"{}\": steps {} of {} have that name: choose one by "
                                    "number (step = {})",
                                    *choice.name, numbers, file.source, named.front()->number));
  }
  return *named.front();
}

}  // namespace

std::string RheometerStep::label() const {
  return name.empty() ? std::to_string(number) : fmt::format("{} '{}'", number, name);
}

RheometerFile read_rheometer_file(const std::filesystem::path& file) {
  return FileReader(file).read();
}

ChosenCurves choose_flow_curves(const RheometerFile& file, const StepChoice& choice) {
  const auto step_name = [&](const RheometerStep& s) {
    return file.steps.size() == 1 ? std::string() : s.label();
  };
  ChosenCurves out;
  if (choice.number || choice.name) {
    const RheometerStep& s = find_step(file, choice);
    if (s.kind != StepKind::FlowCurve)
      fail_choice(choice, fmt::format("step {} of {} is a {} step, not a flow curve", s.label(),
                                      file.source, step_kind_name(s.kind)));
    if (s.problem != RheometerStep::Problem::None) throw InputError(s.why);
    out.curves.push_back({step_name(s), s.curve});
    return out;
  }
  for (const auto& s : file.steps) {
    const bool usable = s.kind == StepKind::FlowCurve && s.problem == RheometerStep::Problem::None;
    if (usable) {
      out.curves.push_back({step_name(s), s.curve});
      continue;
    }
    if (s.problem == RheometerStep::Problem::BadData)
      throw InputError(file.steps.size() == 1
                           ? s.why
                           : fmt::format("{} (step {}; choose the steps to read with step = N in "
                                         "the manifest)",
                                         s.why, s.label()));
    out.skipped += fmt::format("{}step {} ({})", out.skipped.empty() ? "" : ", ", s.label(),
                               s.problem == RheometerStep::Problem::TooFewPoints
                                   ? "too few points"
                                   : std::string(step_kind_name(s.kind)));
  }
  if (!out.curves.empty()) return out;
  if (file.steps.size() == 1 && file.steps.front().problem != RheometerStep::Problem::None)
    throw InputError(file.steps.front().why);
  throw InputError(
      fmt::format("{}: no flow curve in the file (found: {})", file.source, found_steps(file)));
}

FlowCurveFile read_flow_curve_file(const std::filesystem::path& file) {
  const RheometerFile read = read_rheometer_file(file);
  ChosenCurves chosen = choose_flow_curves(read, {});
  if (chosen.curves.size() > 1)
    throw InputError(fmt::format("{}: {} flow-curve steps; choose one (step = N in a manifest)",
                                 read.source, chosen.curves.size()));
  return std::move(chosen.curves.front().curve);
}

std::string step_listing(const RheometerFile& file) {
  std::string out = fmt::format("{}: {} step{}\n", file.source, file.steps.size(),
                                file.steps.size() == 1 ? "" : "s");
  out += fmt::format("  {:>4}  {:<11} {:>6} {:>6}  {:<13} {}\n", "step", "kind", "rows", "points",
                     "lines", "name");
  for (const auto& s : file.steps) {
    const bool curve = s.kind == StepKind::FlowCurve && s.problem == RheometerStep::Problem::None;
    out += fmt::format("  {:>4}  {:<11} {:>6} {:>6}  {:<13} {}\n", s.number, step_kind_name(s.kind),
                       s.rows, curve ? std::to_string(s.curve.points.size()) : "-",
                       fmt::format("{}-{}", s.first_line, s.last_line), s.name);
    if (s.problem != RheometerStep::Problem::None)
      out += "        not used: " + s.why + "\n";
    else if (curve && s.curve.dropped_rows > 0)
      out += "        " + s.curve.dropped + "\n";
  }
  return out;
}

}  // namespace dilatant::analysis
