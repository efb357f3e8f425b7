// Status → Python exception: the one place the binding turns the library's errors into raised
// exceptions. The message is the one the ocean tool prints after "ocean: error: ", in Python's
// names: library fields and the tool's flags rewritten to keywords (params::with_keyword_names
// with the table kSeaStateParameters, ocean/spectrum.hpp): "hs = -1 is out of range: ...".
//
//   invalid_argument → ValueError         io_error → OSError
//   unsupported      → NotImplementedError cancelled → KeyboardInterrupt
//   internal         → RuntimeError
#pragma once

#include <pybind11/pybind11.h>

#include <utility>

#include "ocean/core.hpp"

namespace ocean::python {

/// Raises the Python exception for a failed status (sets the error and throws
/// pybind11::error_already_set). Precondition: !status.ok().
[[noreturn]] void raise(const Status& status);

/// Raises when `status` is not ok.
inline void check(const Status& status) {
  if (!status.ok()) raise(status);
}

/// The value of `result`, or raises its status.
template <class T>
T take(Result<T> result) {
  if (!result.ok()) raise(result.status());
  return std::move(result).value();
}

}  // namespace ocean::python
