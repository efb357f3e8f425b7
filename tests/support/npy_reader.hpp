// tests/support/npy_reader.hpp — the strict .npy reader the tests check written files with.
#pragma once

#include <cstddef>
#include <filesystem>
#include <span>
#include <vector>

#include "ocean/io.hpp"

namespace ocean::io {

/// An array read from a .npy file: `data` holds product(shape) floats in C (row-major) order.
/// An empty `shape` is a 0-d array holding one value.
struct NpyArray {
  std::vector<std::size_t> shape;
  std::vector<float> data;
};

/// Reads a .npy file written by write_npy or numpy.save of a float32 C-order array.
///
/// Contract:
///  - Accepts exactly: magic "\x93NUMPY", version 1.0, a header dict (any key order, ' or "
///    quotes, optional trailing comma, any amount of spaces) with exactly the keys 'descr' =
///    '<f4', 'fortran_order' = False and 'shape' = a tuple of non-negative integers, followed by
///    exactly product(shape) * 4 bytes of data and nothing else.
///  - io_error "cannot read '<path>': <reason>" when the file cannot be opened or read (missing,
///    a directory, permission denied...).
///  - invalid_argument "cannot read '<path>': <problem>" for anything else, naming the problem:
///    wrong magic, unsupported version, malformed or truncated header, a dtype other than '<f4',
///    Fortran order, truncated data, trailing bytes, a shape whose size overflows.
///  - Memory use is bounded by the file size (a header cannot make it allocate more). Never
///    throws; safe on arbitrary bytes.
ocean::Result<NpyArray> read_npy(const std::filesystem::path& path);

}  // namespace ocean::io
