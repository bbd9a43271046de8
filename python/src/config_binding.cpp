// Configurations from Python: a path (io/config.hpp load_config, as `dilatant
// run FILE`) or TOML text (parse_config; a dict arrives as its TOML text,
// dilatant/toml_text.py), each with `--set`-style overrides. Validation is the
// library's, so a bad key or value raises the CLI's one-line message.
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include "bindings.hpp"
#include "io/config.hpp"
#include "toml_convert.hpp"

namespace py = pybind11;

namespace dilatant::python {

namespace {

std::string mode_name(const Config& c) {
  if (c.cell() != nullptr) return "cell";
  if (c.scene() != nullptr) return "scene";
  return "sediment";
}

}  // namespace

void bind_config(py::module_& m) {
  py::class_<Config>(m, "Config",
                     "A validated run configuration (io/config.hpp): every key resolved, "
                     "defaults filled in. Build it with dilatant.load_config().")
      .def_property_readonly(
          "source", [](const Config& c) { return c.source; },
          "The name used in messages: the file, '<dict>' or '<text>'")
      .def_property_readonly("mode", &mode_name, "'cell', 'scene' or 'sediment'")
      .def_property_readonly(
          "notes", [](const Config& c) { return c.notes; },
          "Lines to read before the run (an older resolved config loaded with the meaning its "
          "keys had); dilatant.load_config() issues each as a UserWarning")
      .def(
          "to_dict", [](const Config& c) { return table_to_dict(to_toml(c)); },
          "Every key, defaults filled in, as nested dicts (the resolved config.toml)")
      .def("to_toml", &resolved_toml, "The resolved config.toml a run writes")
      .def("__repr__", [](const Config& c) {
        return "<dilatant.Config " + mode_name(c) + " from " + c.source + ">";
      });

  m.def("config_from_path", &load_config, py::arg("path"), py::arg("overrides"));
  m.def("config_from_text", &parse_config, py::arg("text"), py::arg("source"), py::arg("base_dir"),
        py::arg("overrides"));
  m.def("default_config", &default_cell_config, py::arg("overrides"));
}

}  // namespace dilatant::python
