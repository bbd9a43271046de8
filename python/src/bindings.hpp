#pragma once
// The parts of the `dilatant._core` extension, one file each (docs/python.md).
// The extension wraps library objects (io/config.hpp, drivers/shear_cell.hpp,
// drivers/shear_cell_run.hpp, sweep/, analysis/), never the CLI; the Python
// package (python/dilatant/) adds the conveniences: dict/text/path configs,
// numpy tables, plots.
#include <pybind11/pybind11.h>

namespace dilatant::python {

void bind_config(pybind11::module_& m);      // Config, load/parse
void bind_shear_cell(pybind11::module_& m);  // ShearCell, step by step
void bind_scenes(pybind11::module_& m);      // Scene and Sediment, step by step
void bind_runs(pybind11::module_& m);        // whole runs and sweeps, interruptible
void bind_analysis(pybind11::module_& m);    // analyze
void bind_predict(pybind11::module_& m);     // predict, phase diagram

}  // namespace dilatant::python
