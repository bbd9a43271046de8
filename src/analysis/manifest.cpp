// The analysis manifest (analysis_input.hpp): strict, like the run config —
// every key known, every value typed and in range, every error located.
#include <fmt/format.h>
#include <toml++/toml.h>

#include <algorithm>
#include <cstdint>

#include "analysis/analysis_input.hpp"
#include "analysis/rheometer_file.hpp"
#include "io/input_error.hpp"
#include "io/text.hpp"

namespace dilatant::analysis {
namespace {

// Densest sphere packing: no suspension flows at or above it.
constexpr double kPhiLimit = 0.74;

class ManifestReader {
 public:
  ManifestReader(std::string source, std::filesystem::path base)
      : source_(std::move(source)), base_(std::move(base)) {}

  [[noreturn]] void fail(const toml::node* at, const std::string& what) const {
    if (at != nullptr && at->source().begin.line > 0)
      throw InputError(fmt::format("{}:{}: {}", source_, at->source().begin.line, what));
    throw InputError(fmt::format("{}: {}", source_, what));
  }

  AnalysisInput read(const toml::table& root) {
    for (const auto& [key, node] : root)
      if (key.str() != "curve" && key.str() != "samples")
        fail(&node, fmt::format("unknown key '{}' (known: [[curve]], [samples.NAME])", key.str()));
    AnalysisInput input;
    input.source = source_;
    input.kind = InputKind::Manifest;
    input.units = UnitSystem::SI;
    const toml::node* curves = root.get("curve");
    if (curves == nullptr) fail(nullptr, "no [[curve]] entries: nothing to analyse");
    const toml::array* array = curves->as_array();
    if (array == nullptr || !array->is_array_of_tables())
      fail(curves, "curve: expected an array of tables ([[curve]])");
    for (std::size_t i = 0; i < array->size(); ++i)
      read_curves(*array->get(i)->as_table(), fmt::format("curve[{}]", i), input);
    for (const auto& c : input.curves)
      if (std::find(input.samples.begin(), input.samples.end(), c.sample) == input.samples.end())
        input.samples.push_back(c.sample);
    if (const toml::node* samples = root.get("samples")) read_samples(*samples, input);
    return input;
  }

 private:
  void reject_unknown(const toml::table& t, const std::string& path,
                      std::initializer_list<std::string_view> known) const {
    for (const auto& [key, node] : t) {
      if (std::find(known.begin(), known.end(), key.str()) != known.end()) continue;
      std::string list;
      for (const auto k : known) list += (list.empty() ? "" : ", ") + std::string(k);
      fail(&node, fmt::format("{}.{}: unknown key (known: {})", path, key.str(), list));
    }
  }

  const toml::node& require(const toml::table& t, const std::string& path,
                            std::string_view key) const {
    const toml::node* n = t.get(key);
    if (n == nullptr) fail(&t, fmt::format("{}.{} is missing", path, key));
    return *n;
  }

  double number(const toml::node& n, const std::string& name) const {
    if (const auto v = n.value<double>(); v && (n.is_floating_point() || n.is_integer())) return *v;
    fail(&n, fmt::format("{}: expected a number", name));
  }

  std::string text(const toml::node& n, const std::string& name) const {
    const auto v = n.value<std::string>();
    if (!v || !n.is_string()) fail(&n, fmt::format("{}: expected a string", name));
    if (v->empty()) fail(&n, fmt::format("{} = \"\": must not be empty", name));
    return *v;
  }

  double volume_fraction(const toml::node& n, const std::string& name) const {
    const double phi = number(n, name);
    if (!(phi > 0.0 && phi < kPhiLimit))
      fail(&n, fmt::format("{} = {}: must be in (0, {})", name, phi, kPhiLimit));
    return phi;
  }

  // The [[curve]] entry's curves: one, or one per flow-curve step of its file.
  void read_curves(const toml::table& t, const std::string& path, AnalysisInput& input) const {
    reject_unknown(t, path, {"file", "sample", "phi", "window_stress", "step"});
    FlowCurve c;
    const toml::node& file = require(t, path, "file");
    const std::filesystem::path data = (base_ / text(file, path + ".file")).lexically_normal();
    if (!std::filesystem::is_regular_file(data))
      fail(&file, fmt::format("{}.file = \"{}\": no such file ({})", path,
                              *file.value<std::string>(), data.string()));
    c.source = data.string();
    const toml::node& sample = require(t, path, "sample");
    c.sample = text(sample, path + ".sample");
    if (c.sample.find_first_of(",\"\n\r") != std::string::npos)
      fail(&sample, fmt::format("{}.sample = \"{}\": must not contain ',', '\"' or line breaks",
                                path, c.sample));
    c.phi = volume_fraction(require(t, path, "phi"), path + ".phi");
    if (const toml::node* w = t.get("window_stress")) c.window = read_window(*w, path);
    const StepChoice choice = read_step(t, path);
    const ChosenCurves chosen = choose_flow_curves(read_rheometer_file(data), choice);
    if (!chosen.skipped.empty()) input.skipped_steps.push_back(c.source + ": " + chosen.skipped);
    for (const auto& step : chosen.curves) {
      FlowCurve curve = c;
      curve.step = step.step;
      curve.points = step.curve.points;
      curve.dropped_rows = step.curve.dropped_rows;
      const std::string where = step.step.empty() ? c.source : c.source + " step " + step.step;
      input.note_dropped(where, step.curve.dropped_rows, step.curve.dropped);
      input.curves.push_back(std::move(curve));
    }
  }

  // `step = 2` or `step = "Flow Curve Up"`; neither: every flow-curve step.
  StepChoice read_step(const toml::table& t, const std::string& path) const {
    StepChoice choice;
    const toml::node* n = t.get("step");
    if (n == nullptr) return choice;
    const std::string name = path + ".step";
    choice.origin = fmt::format("{}:{}: {}", source_, n->source().begin.line, name);
    if (n->is_integer()) {
      const auto v = *n->value<std::int64_t>();
      if (v < 1) fail(n, fmt::format("{} = {}: steps are numbered from 1", name, v));
      choice.number = static_cast<std::size_t>(v);
    } else if (n->is_string()) {
      choice.name = text(*n, name);
    } else {
      fail(n, fmt::format("{}: expected a step number (2) or name (\"Flow Curve Up\")", name));
    }
    return choice;
  }

  StressWindow read_window(const toml::node& n, const std::string& path) const {
    const std::string name = path + ".window_stress";
    const toml::array* a = n.as_array();
    if (a == nullptr || a->size() != 2)
      fail(&n, fmt::format("{}: expected [low, high] (shear stress, Pa)", name));
    StressWindow w;
    w.low = number(*a->get(0), name + "[0]");
    w.high = number(*a->get(1), name + "[1]");
    if (!(w.low > 0.0 && w.high > w.low))
      fail(&n, fmt::format("{} = [{}, {}]: needs 0 < low < high", name, w.low, w.high));
    w.origin = fmt::format("{}:{}: {}", source_, n.source().begin.line, name);
    return w;
  }

  void read_samples(const toml::node& node, AnalysisInput& input) const {
    const toml::table* samples = node.as_table();
    if (samples == nullptr) fail(&node, "samples: expected a table ([samples.NAME])");
    for (const auto& [name, entry] : *samples) {
      const std::string path = fmt::format("samples.{}", name.str());
      const toml::table* t = entry.as_table();
      if (t == nullptr) fail(&entry, fmt::format("{}: expected a table ([{}])", path, path));
      const std::string sample(name.str());
      if (std::find(input.samples.begin(), input.samples.end(), sample) == input.samples.end())
        fail(&entry, fmt::format("{}: no [[curve]] has sample = \"{}\"", path, sample));
      reject_unknown(*t, path, {"phi_max"});
      if (const toml::node* pm = t->get("phi_max"))
        input.phi_max[sample] = volume_fraction(*pm, path + ".phi_max");
    }
  }

  std::string source_;
  std::filesystem::path base_;
};

}  // namespace

AnalysisInput read_manifest(const std::filesystem::path& manifest) {
  const std::string source = manifest.string();
  const std::string contents = read_input_file(manifest, "manifest");
  toml::table root;
  try {
    root = toml::parse(contents, source);
  } catch (const toml::parse_error& e) {
    throw InputError(fmt::format("{}:{}:{}: invalid TOML: {}", source, e.source().begin.line,
                                 e.source().begin.column, e.description()));
  }
  return ManifestReader(source, manifest.parent_path()).read(root);
}

}  // namespace dilatant::analysis
