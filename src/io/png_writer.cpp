// src/io/png_writer.cpp — raw-sample PNG writing with libpng's low-level API.
//
// libpng reports errors by longjmp. Every setjmp lives in a small function whose frame holds no
// C++ object with a destructor and no local variable modified after the setjmp, so a longjmp never
// skips a destructor nor reads a clobbered variable.

#include <png.h>

#include <bit>
#include <cerrno>
#include <csetjmp>
#include <cstdio>
#include <exception>
#include <limits>
#include <string>

#include "ocean/io.hpp"
#include "png_detail.hpp"

namespace ocean::io {
namespace {

using detail::png_on_error;
using detail::png_on_warning;
using detail::png_reason;
using detail::PngIo;

void on_write(png_structp png, png_bytep data, std::size_t n) {
  auto* io = static_cast<PngIo*>(png_get_io_ptr(png));
  if (std::fwrite(data, 1, n, io->file) != n) {
    io->err = errno != 0 ? errno : EIO;
    png_error(png, "write failed");
  }
}
void on_flush(png_structp png) {
  auto* io = static_cast<PngIo*>(png_get_io_ptr(png));
  if (std::fflush(io->file) != 0) {
    io->err = errno != 0 ? errno : EIO;
    png_error(png, "write failed");
  }
}

struct Layout {
  int width, height, channels, bit_depth;
  const unsigned char* pixels;
  std::size_t row_bytes;
};

void write_rows(png_structp png, png_infop info, const Layout& l) {
  static constexpr int kColorTypes[] = {PNG_COLOR_TYPE_GRAY, PNG_COLOR_TYPE_GRAY_ALPHA,
                                        PNG_COLOR_TYPE_RGB, PNG_COLOR_TYPE_RGB_ALPHA};
  png_set_IHDR(png, info, static_cast<png_uint_32>(l.width), static_cast<png_uint_32>(l.height),
               l.bit_depth, kColorTypes[l.channels - 1], PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_write_info(png, info);
  // Our 16-bit samples are native-endian; libpng expects big-endian unless told to swap.
  if (l.bit_depth == 16 && std::endian::native == std::endian::little) png_set_swap(png);
  for (int y = 0; y < l.height; ++y) {
    png_write_row(png, l.pixels + static_cast<std::size_t>(y) * l.row_bytes);
  }
  png_write_end(png, nullptr);
}

bool encode(png_structp png, png_infop info, const Layout* layout) {
  if (setjmp(png_jmpbuf(png)) != 0) return false;
  write_rows(png, info, *layout);
  return true;
}

Status write_to(const std::filesystem::path& temporary, const Layout& layout) {
  PngIo io;
  io.file = std::fopen(temporary.c_str(), "wb");
  if (io.file == nullptr) return io_error(errno_message(errno));
  png_structp png =
      png_create_write_struct(PNG_LIBPNG_VER_STRING, &io, png_on_error, png_on_warning);
  png_infop info = png != nullptr ? png_create_info_struct(png) : nullptr;
  if (info == nullptr) {
    png_destroy_write_struct(&png, nullptr);
    std::fclose(io.file);
    return io_error("out of memory");
  }
  png_set_write_fn(png, &io, on_write, on_flush);
  const bool ok = encode(png, info, &layout);
  png_destroy_write_struct(&png, &info);
  if (!ok) {
    std::fclose(io.file);
    return io_error("PNG encoding failed: " + png_reason(io));
  }
  if (std::fclose(io.file) != 0) return io_error(errno_message(errno));
  return Status::ok_status();
}

Status write_png(const std::filesystem::path& path, int width, int height, int channels,
                 int bit_depth, const void* pixels) {
  try {
    if (width < 1 || width > kPngMaxDimension || height < 1 || height > kPngMaxDimension) {
      return invalid_argument("PNG size " + std::to_string(width) + "x" + std::to_string(height) +
                              " is out of range: width and height must be in [1, " +
                              std::to_string(kPngMaxDimension) + "]");
    }
    if (channels < 1 || channels > 4) {
      return invalid_argument("PNG channels = " + std::to_string(channels) +
                              " is out of range: must be 1 (gray), 2 (gray+alpha), 3 (RGB) or "
                              "4 (RGBA)");
    }
    if (pixels == nullptr) return invalid_argument("PNG pixel pointer is null");
    const std::uint64_t row_bytes = static_cast<std::uint64_t>(width) *
                                    static_cast<std::uint64_t>(channels) *
                                    static_cast<std::uint64_t>(bit_depth / 8);
    if (row_bytes * static_cast<std::uint64_t>(height) >
        static_cast<std::uint64_t>(std::numeric_limits<std::ptrdiff_t>::max())) {
      return invalid_argument("PNG image is too large for this machine");
    }
    const Layout layout{width,
                        height,
                        channels,
                        bit_depth,
                        static_cast<const unsigned char*>(pixels),
                        static_cast<std::size_t>(row_bytes)};
    return write_atomically(path, [&layout](const std::filesystem::path& temporary) {
      return write_to(temporary, layout);
    });
  } catch (const std::exception& e) {
    return io_error(
        std::string("cannot write ").append(quoted(path)).append(": ").append(e.what()));
  }
}

}  // namespace

Status write_png8(const std::filesystem::path& path, int width, int height, int channels,
                  const std::uint8_t* pixels) {
  return write_png(path, width, height, channels, 8, pixels);
}

Status write_png16_gray(const std::filesystem::path& path, int width, int height,
                        const std::uint16_t* pixels) {
  return write_png(path, width, height, 1, 16, pixels);
}

}  // namespace ocean::io
