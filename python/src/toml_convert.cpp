#include "toml_convert.hpp"

#include <sstream>

namespace py = pybind11;

namespace dilatant::python {
namespace {

py::object node_to_object(const toml::node& n) {
  if (const auto* t = n.as_table()) return table_to_dict(*t);
  if (const auto* a = n.as_array()) {
    py::list list;
    for (const toml::node& item : *a) list.append(node_to_object(item));
    return list;
  }
  if (const auto v = n.value_exact<bool>()) return py::bool_(*v);
  if (const auto v = n.value_exact<std::int64_t>()) return py::int_(*v);
  if (const auto v = n.value_exact<double>()) return py::float_(*v);
  if (const auto v = n.value_exact<std::string>()) return py::str(*v);
  // Dates and times: no key of ours has one; keep their TOML text.
  std::ostringstream text;
  text << toml::toml_formatter(n);
  return py::str(text.str());
}

}  // namespace

py::dict table_to_dict(const toml::table& t) {
  py::dict d;
  for (const auto& [k, v] : t) d[py::str(std::string(k.str()))] = node_to_object(v);
  return d;
}

}  // namespace dilatant::python
