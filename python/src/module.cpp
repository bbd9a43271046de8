// dilatant._core: the compiled half of the `dilatant` Python module.
//
// Errors: InputError (bad input: a key, a value, a file; the CLI's exit 2)
// becomes dilatant.ConfigError, a ValueError whose message is exactly the
// line the CLI prints after "dilatant: error: ". Any other library error is a
// RuntimeError (pybind11's translation of std::runtime_error).
#include <pybind11/pybind11.h>

#include "bindings.hpp"
#include "dilatant/version.hpp"
#include "io/input_error.hpp"

PYBIND11_MODULE(_core, m) {
  m.doc() = "dilatant's engine (libdilatant): configs, shear cells, runs, sweeps, analysis";
  m.attr("__version__") = dilatant::kVersion;
  pybind11::register_exception<dilatant::InputError>(m, "ConfigError", PyExc_ValueError);
  dilatant::python::bind_config(m);
  dilatant::python::bind_shear_cell(m);
  dilatant::python::bind_scenes(m);
  dilatant::python::bind_runs(m);
  dilatant::python::bind_analysis(m);
  dilatant::python::bind_predict(m);
}
