// numpy helpers of the binding: float64 inputs of any shape and the outputs shaped like them.
#pragma once

#include <pybind11/numpy.h>

#include <cstddef>

namespace ocean::python {

/// A C-contiguous float64 array (a copy only when the input is another type or layout).
using DoubleArray =
    pybind11::array_t<double, pybind11::array::c_style | pybind11::array::forcecast>;

/// An uninitialised float64 array with the shape of `like`.
inline DoubleArray empty_like(const DoubleArray& like) {
  return DoubleArray(std::vector<pybind11::ssize_t>(like.shape(), like.shape() + like.ndim()));
}

/// y[i] = f(x[i]) over every element, x and y of one shape.
template <class F>
DoubleArray map_values(const DoubleArray& x, F&& f) {
  DoubleArray y = empty_like(x);
  const double* in = x.data();
  double* out = y.mutable_data();
  for (pybind11::ssize_t i = 0; i < x.size(); ++i) out[i] = f(in[i]);
  return y;
}

}  // namespace ocean::python
