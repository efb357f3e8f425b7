// Status → Python exception (see errors.hpp).
#include "errors.hpp"

#include "ocean/parameters.hpp"
#include "ocean/spectrum.hpp"

namespace ocean::python {

[[noreturn]] void raise(const Status& status) {
  PyObject* type = PyExc_RuntimeError;
  switch (status.code()) {
    case ErrorCode::invalid_argument: type = PyExc_ValueError; break;
    case ErrorCode::io_error: type = PyExc_OSError; break;
    case ErrorCode::unsupported: type = PyExc_NotImplementedError; break;
    case ErrorCode::cancelled: type = PyExc_KeyboardInterrupt; break;
    case ErrorCode::ok:
    case ErrorCode::internal: break;
  }
  PyErr_SetString(type, params::with_keyword_names(status.message(), kSeaStateParameters).c_str());
  throw pybind11::error_already_set();
}

}  // namespace ocean::python
