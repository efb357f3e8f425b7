// src/io/png_detail.hpp — libpng's error plumbing, shared by the PNG writer, the height map reader
// (src/waves) and the test reader (tests/support): the state a callback fills and the callbacks
// libpng calls.
#pragma once

#include <png.h>
#include <sys/stat.h>

#include <cerrno>
#include <cstdint>
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

/// Walks the chunks of the PNG file `file` (positioned anywhere; left at its start) before libpng
/// reads it. libpng allocates a chunk's declared length before it reads the data, so a file of a
/// few dozen bytes could make it allocate 2 GB. Refused, with the reason returned (empty when the
/// file may be read): a file that is not a regular file, a chunk that declares more bytes than
/// the file holds after it, and any chunk but IDAT that declares more than kPngMaxChunkBytes.
/// IDAT is streamed through zlib in small pieces, so its length costs no allocation.
///
/// This work is based on: [PNG Specification] (docs/references.md), §5.3 Chunk layout: a 4-byte
/// big-endian length of at most 2^31 − 1, a 4-byte type, the data and a 4-byte CRC.
inline std::string check_png_chunks(std::FILE* file) {
  struct stat st {};
  if (::fstat(::fileno(file), &st) != 0) return errno_message(errno);
  if (!S_ISREG(st.st_mode)) return "it is not a regular file";
  const auto file_size = static_cast<std::uint64_t>(st.st_size);
  std::uint64_t pos = 8;  // after the signature (libpng checks the signature itself)
  std::string problem;
  while (pos + 8 <= file_size) {
    unsigned char head[8];
    if (std::fseek(file, static_cast<long>(pos), SEEK_SET) != 0 ||
        std::fread(head, 1, sizeof head, file) != sizeof head) {
      problem = "truncated file";
      break;
    }
    const std::uint64_t length = (std::uint64_t{head[0]} << 24U) | (std::uint64_t{head[1]} << 16U) |
                                 (std::uint64_t{head[2]} << 8U) | std::uint64_t{head[3]};
    std::string type;
    for (int i = 4; i < 8; ++i) {
      const unsigned char c = head[i];
      const bool letter = (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z');
      if (!letter) {
        type.clear();
        break;
      }
      type.push_back(static_cast<char>(c));
    }
    if (type.empty()) {
      problem = "a chunk type is not four letters";
      break;
    }
    const std::uint64_t after = file_size - pos - 8;
    if (length > after) {
      problem = "chunk '" + type + "' declares " + std::to_string(length) +
                " bytes, more than the file holds";
      break;
    }
    if (type != "IDAT" && length > kPngMaxChunkBytes) {
      problem = "chunk '" + type + "' declares " + std::to_string(length) +
                " bytes, more than the reader's limit of " + byte_limit_text(kPngMaxChunkBytes);
      break;
    }
    if (type == "IEND") break;
    pos += 12 + length;
  }
  std::rewind(file);
  return problem;
}

/// The limits set on every reading png_struct: chunk allocations (decompressed text and ICC
/// profiles included) at most kPngMaxChunkBytes, at most 1000 ancillary chunks cached.
inline void limit_png_reader(png_structp png) {
  png_set_chunk_malloc_max(png, kPngMaxChunkBytes);
  png_set_chunk_cache_max(png, 1000);
}

}  // namespace ocean::io::detail
