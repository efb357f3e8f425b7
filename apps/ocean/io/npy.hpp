// io/npy.hpp — NumPy .npy (format 1.0, little-endian float32, C order) writer and strict reader.
#pragma once

#include <cstddef>
#include <filesystem>
#include <span>
#include <vector>

#include "ocean/core.hpp"

namespace ocean::io {

/// Largest number of dimensions write_npy and read_npy accept (NumPy 1.x's NPY_MAXDIMS).
inline constexpr std::size_t kNpyMaxDims = 32;

/// An array read from a .npy file: `data` holds product(shape) floats in C (row-major) order.
/// An empty `shape` is a 0-d array holding one value.
struct NpyArray {
  std::vector<std::size_t> shape;
  std::vector<float> data;
};

/// Writes `data` as a NumPy .npy file (format version 1.0, dtype '<f4', fortran_order False).
///
/// Contract:
///  - `data` points to product(shape) floats in C order (last index fastest); it may be null only
///    when that product is 0. An empty `shape` writes a 0-d array of one value.
///  - The header is laid out byte for byte as numpy.save writes it (including its spare space for
///    growing the first axis), padded with spaces and ended by '\n' so that the data start at a
///    multiple of 64 bytes. Values are stored bit-exactly (NaN payloads included), little-endian.
///  - Written atomically (see write_atomically): on failure `path` keeps its old contents.
///  - invalid_argument for more than kNpyMaxDims dimensions, a size that overflows, or null data;
///    io_error "cannot write '<path>': <reason>" for file system failures. Never throws.
ocean::Status write_npy(const std::filesystem::path& path, const float* data,
                        std::span<const std::size_t> shape);

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
