// dilatant._core: the compiled half of the `dilatant` Python module.
//
// Errors: InputError (bad input: a key, a value, a file; the CLI's exit 2)
// becomes dilatant.ConfigError, a ValueError whose message is exactly the
// line the CLI prints after "dilatant: error: ". Any other library error is a
// RuntimeError (pybind11's translation of std::runtime_error). An output
// folder that cannot be used (io/output_folder.hpp) is the built-in OSError
// subclass of its errno, as os.makedirs would raise: FileExistsError,
// NotADirectoryError, PermissionError, else OSError.
#include <pybind11/pybind11.h>

#include "bindings.hpp"
#include "dilatant/version.hpp"
#include "io/input_error.hpp"
#include "io/output_folder.hpp"

PYBIND11_MODULE(_core, m) {
  m.doc() = "dilatant's engine (libdilatant): configs, shear cells, runs, sweeps, analysis";
  m.attr("__version__") = dilatant::kVersion;
  pybind11::register_exception<dilatant::InputError>(m, "ConfigError", PyExc_ValueError);
  // Registered after ConfigError's, so tried before it: the more derived type.
  pybind11::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const dilatant::OutputFolderError& e) {
      // OSError(errno, message) constructs the subclass that errno maps to.
      pybind11::tuple args = pybind11::make_tuple(e.error_number(), e.what());
      PyErr_SetObject(PyExc_OSError, args.ptr());
    }
  });
  dilatant::python::bind_config(m);
  dilatant::python::bind_shear_cell(m);
  dilatant::python::bind_scenes(m);
  dilatant::python::bind_runs(m);
  dilatant::python::bind_analysis(m);
  dilatant::python::bind_predict(m);
}
