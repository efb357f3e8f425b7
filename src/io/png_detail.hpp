// src/io/png_detail.hpp — libpng's error plumbing, shared by the PNG writer, the height map reader
// (src/waves) and the test reader (tests/support): the state a callback fills and the callbacks
// libpng calls.
#pragma once

#include <png.h>

#include <cerrno>
#include <cstdio>
#include <string>

#include "ocean/io.hpp"

namespace ocean::io::detail {

/// The open file, the errno of a failed read or write, and the message of the libpng error
/// that aborted the operation.
struct PngIo {
  std::FILE* file = nullptr;
  int err = 0;
  char message[256] = {};
};

/// libpng's error callback: keeps the message and unwinds to the caller's setjmp.
inline void png_on_error(png_structp png, png_const_charp message) {
  auto* io = static_cast<PngIo*>(png_get_error_ptr(png));
  std::snprintf(io->message, sizeof io->message, "%s", message != nullptr ? message : "error");
  png_longjmp(png, 1);
}
/// libpng's warning callback: warnings are not errors and are dropped.
inline void png_on_warning(png_structp /*png*/, png_const_charp /*message*/) {}

/// libpng's read callback for a PngIo set with png_set_read_fn: a short read is an error
/// ("read failed" with the errno kept, or "truncated file").
inline void png_on_read(png_structp png, png_bytep data, std::size_t n) {
  auto* io = static_cast<PngIo*>(png_get_io_ptr(png));
  if (std::fread(data, 1, n, io->file) != n) {
    if (std::ferror(io->file) != 0) io->err = errno != 0 ? errno : EIO;
    png_error(png, io->err != 0 ? "read failed" : "truncated file");
  }
}

/// Why the operation failed: the I/O errno when there was one, else libpng's message.
inline std::string png_reason(const PngIo& io) {
  return io.err != 0 ? errno_message(io.err) : std::string(io.message);
}

}  // namespace ocean::io::detail
