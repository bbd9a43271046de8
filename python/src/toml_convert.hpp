#pragma once
// A resolved configuration back to Python: the TOML table as nested dicts
// ({"cell": {"size": [6.0, 5.0, 7.0]}, ...}), the structure a dict config has.
// (A dict config goes the other way as TOML text: dilatant/toml_text.py.)
#include <pybind11/pybind11.h>
#include <toml++/toml.h>

namespace dilatant::python {

pybind11::dict table_to_dict(const toml::table& t);

}  // namespace dilatant::python
