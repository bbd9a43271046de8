#include "sweep/unsteady_extension.hpp"

#include <fmt/format.h>
#include <toml++/toml.h>

#include <cmath>
#include <stdexcept>
#include <string>

#include "drivers/shear_cell_run.hpp"

namespace dilatant::sweep {
namespace {

double window(const Config& planned) { return planned.run.strain - planned.run.transient_strain; }

// To 12 significant digits: 0.3 + 3 x 0.2 is 0.9 in config.toml, not
// 0.8999999999999999 (the folder's text is compared, and read by people).
double rounded(double x) { return std::stod(fmt::format("{:.12g}", x)); }

}  // namespace

Config extended_config(const Config& planned, int k) {
  if (k <= 0) return planned;
  Config c = planned;
  const double w = window(planned);
  c.run.strain = rounded(planned.run.strain + k * w);
  c.run.transient_strain = rounded(planned.run.strain + (k - 1) * w);
  c.resolved = to_toml(c);
  return c;
}

int extensions_in(const std::string& config_text, const Config& planned, double cap) {
  toml::table there;
  try {
    there = toml::parse(config_text);
  } catch (const toml::parse_error&) {
    return 0;  // the caller's comparison says what is wrong with it
  }
  const double strain = there["run"]["strain"].value_or(planned.run.strain);
  const double w = window(planned);
  if (!(w > 0.0) || !(strain > planned.run.strain)) return 0;
  const double k = std::round((strain - planned.run.strain) / w);
  if (k < 1.0 || k > 1e6) return 0;
  const Config extended = extended_config(planned, static_cast<int>(k));
  // Within a rounding of the text: the folder's values were written from
  // these very doubles.
  const auto close = [](double a, double b) { return std::abs(a - b) <= 1e-9 * std::abs(b); };
  const double transient = there["run"]["transient_strain"].value_or(0.0);
  if (!close(strain, extended.run.strain) || !close(transient, extended.run.transient_strain) ||
      extended.run.strain > cap * (1.0 + 1e-12))
    return 0;
  return static_cast<int>(k);
}

bool needs_extension(const nlohmann::json& summary, const Config& current, double cap) {
  const auto steady = summary.find("steady");
  if (steady == summary.end() || !steady->is_boolean() || steady->get<bool>()) return false;
  if (summary.value("jammed", false)) return false;
  const double next = current.run.strain + (current.run.strain - current.run.transient_strain);
  return next <= cap * (1.0 + 1e-12);
}

std::string extension_note(const std::string& folder, const nlohmann::json& summary,
                           const Config& next, double cap) {
  return fmt::format(
      "dilatant: {}: not steady at strain {:g} (wall speed drift {:+.0f}% +- {:.0f}%): runs on "
      "to strain {:g}, averaging past {:g} (sweep.extend_unsteady_to = {:g})",
      folder, next.run.transient_strain, 100.0 * summary.value("wall_velocity_drift", 0.0),
      100.0 * summary.value("wall_velocity_drift_err", 0.0), next.run.strain,
      next.run.transient_strain, cap);
}

bool run_on_while_unsteady(const ExtensionRun& run, int& extensions, nlohmann::json& summary) {
  while (needs_extension(summary, extended_config(run.planned, extensions), run.cap)) {
    if (run.halt != nullptr && run.halt->load()) return true;
    const Config next = extended_config(run.planned, extensions + 1);
    if (run.note) run.note(extension_note(run.name, summary, next, run.cap));
    std::filesystem::remove(run.folder / "summary.json");
    ++extensions;
    CellRunOptions o;
    o.run.out_dir = run.folder;
    o.run.quiet = true;
    o.resume = true;
    o.stop_requested = run.halt;
    o.progress = run.progress;
    CellOutcome outcome = run_shear_cell(next, o);
    if (outcome.interrupted) return false;
    if (!outcome.summary.is_object())
      throw std::runtime_error(fmt::format("{}: the run on to strain {:g} wrote no summary",
                                           run.folder.string(), next.run.strain));
    summary = std::move(outcome.summary);
  }
  return true;
}

}  // namespace dilatant::sweep
