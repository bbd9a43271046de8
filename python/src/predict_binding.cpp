// The regime predictor (analysis/prediction_report.hpp, `dilatant predict`,
// the bulk flow states before the sediment table)
// and its phase diagram (analysis/phase_diagram.hpp, `predict --grid`), and the
// answer from a Wyart–Cates fit (`predict --model FILE`).
#include <fmt/format.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <cmath>
#include <optional>
#include <string>

#include "analysis/phase_diagram.hpp"
#include "analysis/prediction_report.hpp"
#include "analysis/wyart_cates_prediction.hpp"
#include "bindings.hpp"
#include "friction/defaults.hpp"
#include "io/atomic_file.hpp"
#include "io/input_error.hpp"
#include "io/output_folder.hpp"

namespace py = pybind11;

namespace dilatant::python {

namespace {

analysis::JammingTable table_of(const std::optional<std::filesystem::path>& file) {
  return file ? analysis::JammingTable::read(*file) : analysis::JammingTable::builtin();
}

// As the CLI's --bulk-table: None the built-in table, "none" no bulk source.
std::optional<analysis::BulkFlowTable> bulk_table_of(const std::optional<std::string>& file) {
  if (!file) return analysis::BulkFlowTable::builtin();
  if (*file == "none") return std::nullopt;
  return analysis::BulkFlowTable::read(*file);
}

const analysis::BulkFlowTable* bulk_pointer(const std::optional<analysis::BulkFlowTable>& t) {
  return t ? &*t : nullptr;
}

// s_c None: the Stribeck law's default (friction/defaults.hpp), as the CLI's.
py::object predict(double mu0, double phi, std::optional<double> s_c,
                   const std::optional<std::filesystem::path>& table,
                   const std::optional<std::string>& bulk_table) {
  const double s = s_c.value_or(friction_defaults::kSc);
  const analysis::PredictArgumentNames names{"mu0", "phi", "s_c"};
  analysis::check_prediction_input(mu0, phi, s, names);  // before the table is read
  const auto bulk = bulk_table_of(bulk_table);
  const auto report = analysis::predict(table_of(table), bulk_pointer(bulk), mu0, phi, s, names);
  const std::string text =
      analysis::prediction_json(report, table ? table->string() : "built-in").dump();
  return py::module_::import("json").attr("loads")(text);
}

void phase_diagram(const std::filesystem::path& out,
                   const std::optional<std::filesystem::path>& table,
                   const std::optional<std::string>& bulk_table) {
  const auto bulk = bulk_table_of(bulk_table);
  prepare_output_folder(out);
  write_file_atomically(out / "phase_diagram.csv",
                        analysis::phase_diagram_csv(table_of(table), bulk_pointer(bulk), {}));
}

// The regime from a Wyart–Cates fit (analysis/wyart_cates_prediction.hpp),
// as `dilatant predict --model FILE --json`.
py::object predict_from_fit(const std::filesystem::path& model, double phi,
                            std::optional<double> stress, const std::string& sample) {
  if (!(phi > 0.0 && phi < 1.0)) throw InputError(fmt::format("phi {}: must be in (0, 1)", phi));
  if (stress && !(*stress > 0.0 && std::isfinite(*stress)))
    throw InputError(fmt::format("stress {}: must be a finite number > 0", *stress));
  const auto fit = analysis::read_fitted_wyart_cates(model, sample, "sample");
  const std::string text = analysis::wyart_cates_prediction(fit, phi, stress).dump();
  return py::module_::import("json").attr("loads")(text);
}

}  // namespace

void bind_predict(py::module_& m) {
  m.def("predict", &predict, py::arg("mu0"), py::arg("phi"), py::arg("s_c"), py::arg("table"),
        py::arg("bulk_table"));
  m.def("predict_from_fit", &predict_from_fit, py::arg("model"), py::arg("phi"), py::arg("stress"),
        py::arg("sample"));
  m.def("phase_diagram", &phase_diagram, py::arg("out"), py::arg("table"), py::arg("bulk_table"));
}

}  // namespace dilatant::python
