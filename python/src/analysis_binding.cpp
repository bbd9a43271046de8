// The rheometer analysis (analysis/analysis.hpp, `dilatant analyze`) and the
// Wyart–Cates fit (analysis/wyart_cates_report.hpp, `analyze --model wyart-cates`).
// Settings are checked here with the names Python spells them
// (onset_factor=..., not --onset-factor).
#include <fmt/format.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <array>
#include <cctype>
#include <optional>
#include <string>
#include <string_view>

#include "analysis/analysis.hpp"
#include "analysis/report_files.hpp"
#include "analysis/rheometer_file.hpp"
#include "analysis/wyart_cates_report.hpp"
#include "bindings.hpp"
#include "io/input_error.hpp"
#include "io/output_folder.hpp"

namespace py = pybind11;

namespace dilatant::python {

namespace {

void check(bool ok, std::string_view name, double value, std::string_view what) {
  if (!ok) throw InputError(fmt::format("{} = {}: {}", name, value, what));
}

// The value of a choice among its names (analysis::ChoiceName), case aside as
// the CLI reads --wc-phi and --wc-weights; another is bad input naming them.
template <class Choice, std::size_t N>
Choice choice(std::string_view name, const std::string& value,
              const std::array<analysis::ChoiceName<Choice>, N>& names) {
  const auto lower = [](std::string_view text) {
    std::string out(text);
    for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return out;
  };
  std::string allowed;
  for (const analysis::ChoiceName<Choice>& c : names) {
    if (lower(value) == lower(c.name)) return c.value;
    allowed += fmt::format("{}{}", allowed.empty() ? "" : ", ", c.name);
  }
  throw InputError(fmt::format("{} = '{}': must be one of {}", name, value, allowed));
}

// Writes curves.csv, points.csv and fits.json into `out`; returns the numbers
// of curves and samples (the files hold the rest).
// A setting left None keeps the library's default (analysis_settings.hpp).
py::dict analyse(const std::filesystem::path& input, const std::filesystem::path& out,
                 std::optional<double> onset_factor, std::optional<double> dst_n_cap,
                 std::optional<int> min_window_points, std::optional<double> confidence) {
  analysis::AnalysisSettings s;
  s.onset_factor = onset_factor.value_or(s.onset_factor);
  s.dst_n_cap = dst_n_cap.value_or(s.dst_n_cap);
  s.min_window_points = min_window_points.value_or(s.min_window_points);
  s.confidence = confidence.value_or(s.confidence);
  check(s.onset_factor > 1.0, "onset_factor", s.onset_factor, "must be > 1");
  check(s.dst_n_cap > 0.0, "dst_n_cap", s.dst_n_cap, "must be > 0");
  check(s.min_window_points >= 3, "min_window_points", s.min_window_points, "must be >= 3");
  check(s.confidence > 0.0 && s.confidence < 1.0, "confidence", s.confidence, "must be in (0, 1)");
  std::size_t curves = 0, samples = 0;
  {
    py::gil_scoped_release release;
    const analysis::AnalysisReport report =
        analysis::analyse(analysis::load_analysis_input(input), s);
    analysis::write_report_files(report, out);
    curves = report.curves.size();
    samples = report.samples.size();
  }
  py::dict d;
  d["curves"] = curves;
  d["samples"] = samples;
  return d;
}

// The steps of a rheometer export (`dilatant analyze --list`), one dict each.
py::list rheometer_steps(const std::filesystem::path& file) {
  const analysis::RheometerFile read = analysis::read_rheometer_file(file);
  py::list steps;
  for (const auto& s : read.steps) {
    const bool curve = s.kind == analysis::StepKind::FlowCurve &&
                       s.problem == analysis::RheometerStep::Problem::None;
    py::dict d;
    d["number"] = s.number;
    d["name"] = s.name;
    d["kind"] = std::string(analysis::step_kind_name(s.kind));
    d["rows"] = s.rows;
    d["points"] = curve ? py::object(py::int_(s.curve.points.size())) : py::object(py::none());
    d["dropped_rows"] = s.curve.dropped_rows;
    d["first_line"] = s.first_line;
    d["last_line"] = s.last_line;
    d["problem"] = s.why.empty() ? py::object(py::none()) : py::object(py::str(s.why));
    steps.append(d);
  }
  return steps;
}

// The Wyart–Cates fit of every sample (analysis/wyart_cates_report.hpp):
// writes wyart_cates.json, wyart_cates_curves.csv and wyart_cates_map.csv into
// `out`; phi and weights are named as --wc-phi's and --wc-weights' values.
// Returns the numbers of samples and of fitted ones. No sample fitted is a
// ConfigError naming each one's reason, as the CLI's exit 2.
py::dict fit_wyart_cates(const std::filesystem::path& input, const std::filesystem::path& out,
                         std::optional<double> alpha, std::optional<double> beta, bool fit_alpha,
                         bool fit_beta, const std::string& phi, const std::string& weights) {
  analysis::WyartCatesSettings s;
  s.alpha = alpha.value_or(s.alpha);
  s.beta = beta.value_or(s.beta);
  s.fit_alpha = fit_alpha;
  s.fit_beta = fit_beta;
  s.phi = choice("phi_basis", phi, analysis::kPhiBasisNames);
  s.weights = choice("weights", weights, analysis::kWeightsNames);
  check(s.alpha > 0.0 && s.alpha < 20.0, "alpha", s.alpha, "must be in (0, 20)");
  check(s.beta > 0.0 && s.beta < 20.0, "beta", s.beta, "must be in (0, 20)");
  std::size_t samples = 0, fitted = 0;
  {
    py::gil_scoped_release release;
    const analysis::WyartCatesReport report =
        analysis::wyart_cates_report(analysis::load_analysis_input(input), s);
    std::string why;
    for (const auto& sample : report.samples) {
      ++samples;
      if (sample.outcome.fit)
        ++fitted;
      else
        why +=
            fmt::format("{}{}: {}", why.empty() ? "" : "; ", sample.sample, sample.outcome.why_not);
    }
    if (fitted == 0) throw InputError(fmt::format("no sample could be fitted ({})", why));
    prepare_output_folder(out);
    analysis::write_wyart_cates_files(report, out);
  }
  py::dict d;
  d["samples"] = samples;
  d["fitted"] = fitted;
  return d;
}

}  // namespace

void bind_analysis(py::module_& m) {
  m.def("analyse", &analyse, py::arg("input"), py::arg("out"), py::arg("onset_factor"),
        py::arg("dst_n_cap"), py::arg("min_window_points"), py::arg("confidence"));
  m.def("rheometer_steps", &rheometer_steps, py::arg("file"));
  m.def("fit_wyart_cates", &fit_wyart_cates, py::arg("input"), py::arg("out"), py::arg("alpha"),
        py::arg("beta"), py::arg("fit_alpha"), py::arg("fit_beta"), py::arg("phi"),
        py::arg("weights"));
}

}  // namespace dilatant::python
