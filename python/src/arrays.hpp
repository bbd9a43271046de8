#pragma once
// numpy copies of the engine's per-body vectors: the object goes on stepping
// after the caller got them, so they are copies, never views.
#include <pybind11/numpy.h>

#include <vector>

#include "geometry/vec3.hpp"

namespace dilatant::python {

// (N, 3) float64.
inline pybind11::array_t<double> vectors(const std::vector<Vec3>& v) {
  pybind11::array_t<double> a({static_cast<pybind11::ssize_t>(v.size()), pybind11::ssize_t{3}});
  auto out = a.mutable_unchecked<2>();
  for (std::size_t i = 0; i < v.size(); ++i)
    for (int k = 0; k < 3; ++k) out(static_cast<pybind11::ssize_t>(i), k) = v[i][k];
  return a;
}

// (N,) of T.
template <class T>
pybind11::array_t<T> values(const std::vector<T>& v) {
  return pybind11::array_t<T>(static_cast<pybind11::ssize_t>(v.size()), v.data());
}

}  // namespace dilatant::python
