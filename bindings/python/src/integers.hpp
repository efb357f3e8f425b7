// Integer arguments: a Python int of any size reaches the binding whole, so that a value beyond
// the C++ type is refused with the range it must lie in, as any other value out of range is,
// instead of wrapping around or failing pybind11's own conversion with a TypeError about the
// function's signature.
#pragma once

#include <pybind11/pybind11.h>

#include <climits>
#include <string>

#include "errors.hpp"
#include "ocean/parameters.hpp"

namespace ocean::python {

/// A Python integer argument: an int or an object with __index__ (numpy.int64), not a float,
/// exactly what pybind11 converts to a C++ integer. Its value saturates at the ends of long long;
/// its text is the exact value as Python writes it, for the message that refuses it.
struct Integer {
  long long value = 0;  ///< LLONG_MIN or LLONG_MAX for a value beyond 64 bits
  std::string text;
};

/// The `threads` argument of Simulator and surface_stats: 0 (every hardware thread) to 256, the
/// most threads `ocean bench --threads` and make_ready_runner take. oneTBB itself has no bound:
/// an arena of 10**9 slots crashes it.
inline constexpr params::NumberOption<double> kThreads{
    .flag = "threads", .lo = 0, .hi = 256, .says = "an integer in [0, 256] (0: all threads)"};

/// `arg` when it lies in [option.lo, option.hi], else ValueError with the tool's message
/// "<flag> = <arg> is out of range: must be an integer in [lo, hi]" (or "must be <says>"),
/// the value echoed exactly. The bounds must be within ±2^53 (exact as doubles).
inline long long in_range(const Integer& arg, params::NumberOption<double> option) {
  option.accept = params::Accept::integer_in_range;
  option.echo = params::Echo::text;
  check(params::check(option, static_cast<double>(arg.value), arg.text));
  return arg.value;
}

}  // namespace ocean::python

namespace pybind11::detail {

template <>
struct type_caster<ocean::python::Integer> {
  PYBIND11_TYPE_CASTER(ocean::python::Integer, const_name("int"));

  bool load(handle src, bool /*convert*/) {
    if (!src || PyFloat_Check(src.ptr()) || !PyIndex_Check(src.ptr())) return false;
    const auto index = reinterpret_steal<object>(PyNumber_Index(src.ptr()));
    if (!index) {
      PyErr_Clear();
      return false;
    }
    int overflow = 0;
    const long long v = PyLong_AsLongLongAndOverflow(index.ptr(), &overflow);
    if (v == -1 && PyErr_Occurred()) {
      PyErr_Clear();
      return false;
    }
    value.value = overflow > 0 ? LLONG_MAX : overflow < 0 ? LLONG_MIN : v;
    value.text = std::to_string(v);
    if (overflow != 0) {
      // str() refuses integers of more than sys.get_int_max_str_digits() digits.
      const auto text = reinterpret_steal<object>(PyObject_Str(index.ptr()));
      if (text) {
        value.text = text.cast<std::string>();
      } else {
        PyErr_Clear();
        value.text = overflow > 0 ? "(an integer too long to print)"
                                  : "(a negative integer too long to print)";
      }
    }
    return true;
  }

  static handle cast(const ocean::python::Integer& v, return_value_policy /*policy*/,
                     handle /*parent*/) {
    return PyLong_FromLongLong(v.value);
  }
};

}  // namespace pybind11::detail
