// ocean._ocean: the extension module under the `ocean` Python package (bindings/python/ocean).
#include <pybind11/pybind11.h>

#include "bindings.hpp"

PYBIND11_MODULE(_ocean, m) {
  m.doc() = "Spectral ocean surface simulation (the C++ library ocean, wrapped with pybind11).";
  m.attr("__version__") = OCEAN_VERSION;  // the project's version (CMakeLists.txt)
  ocean::python::bind_spectrum(m);
  ocean::python::bind_preset(m);
  ocean::python::bind_sea_state(m);
  ocean::python::bind_simulator(m);
  ocean::python::bind_bake(m);
}
