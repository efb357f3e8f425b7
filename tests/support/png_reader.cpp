// tests/support/png_reader.cpp — raw-sample PNG reading with libpng's low-level API.
//
// libpng reports errors by longjmp. Every setjmp lives in a small function whose frame holds no
// C++ object with a destructor and no local variable modified after the setjmp, so a longjmp never
// skips a destructor nor reads a clobbered variable.
#include "support/png_reader.hpp"

#include <png.h>

#include <bit>
#include <cerrno>
#include <csetjmp>
#include <cstdio>
#include <exception>
#include <limits>
#include <string>

#include "io/png_detail.hpp"
#include "ocean/io.hpp"

namespace ocean::io {
namespace {

using detail::png_on_error;
using detail::png_on_warning;
using detail::png_reason;
using detail::PngIo;

constexpr std::uint64_t kMaxSampleBytes = std::uint64_t{1} << 30;

bool read_header(png_structp png, png_infop info) {
  if (setjmp(png_jmpbuf(png)) != 0) return false;
  png_read_info(png, info);
  png_set_expand(png);  // palette -> RGB, gray < 8 bits -> 8 bits, tRNS -> alpha
  (void)png_set_interlace_handling(png);
  png_read_update_info(png, info);
  return true;
}

bool read_rows(png_structp png, png_infop info, png_bytepp rows) {
  if (setjmp(png_jmpbuf(png)) != 0) return false;
  png_read_image(png, rows);
  png_read_end(png, info);  // checks the chunks after the image data up to IEND
  return true;
}

Result<PngImage> read_opened(PngIo& io, const std::filesystem::path& path) {
  const auto fail = [&](const std::string& why) -> Status {
    return io_error(std::string("cannot read '").append(path.string()).append("': ").append(why));
  };
  png_structp png =
      png_create_read_struct(PNG_LIBPNG_VER_STRING, &io, png_on_error, png_on_warning);
  png_infop info = png != nullptr ? png_create_info_struct(png) : nullptr;
  if (info == nullptr) {
    png_destroy_read_struct(&png, nullptr, nullptr);
    return fail("out of memory");
  }
  struct Destroy {
    png_structp* png;
    png_infop* info;
    ~Destroy() { png_destroy_read_struct(png, info, nullptr); }
  } destroy{&png, &info};
  png_set_read_fn(png, &io, detail::png_on_read);
  png_set_user_limits(png, kPngMaxDimension, kPngMaxDimension);
  detail::limit_png_reader(png);
  if (std::string problem = detail::check_png_chunks(io.file); !problem.empty())
    return fail(problem);
  if (!read_header(png, info)) return fail(png_reason(io));

  PngImage image;
  image.width = static_cast<int>(png_get_image_width(png, info));
  image.height = static_cast<int>(png_get_image_height(png, info));
  image.channels = png_get_channels(png, info);
  image.bit_depth = png_get_bit_depth(png, info);
  const std::size_t row_bytes = png_get_rowbytes(png, info);
  const auto h = static_cast<std::size_t>(image.height);
  const auto samples_per_row =
      static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.channels);
  if (image.channels < 1 || image.channels > 4 || (image.bit_depth != 8 && image.bit_depth != 16) ||
      row_bytes != samples_per_row * static_cast<std::size_t>(image.bit_depth / 8)) {
    return fail("unexpected PNG layout after expansion");
  }
  if (static_cast<std::uint64_t>(row_bytes) * h > kMaxSampleBytes) {
    return fail("image is too large to read (more than 1 GiB of samples)");
  }
  std::vector<png_byte> bytes(row_bytes * h);
  std::vector<png_bytep> rows(h);
  for (std::size_t y = 0; y < h; ++y) rows[y] = bytes.data() + y * row_bytes;
  if (!read_rows(png, info, rows.data())) return fail(png_reason(io));

  image.samples.resize(samples_per_row * h);
  if (image.bit_depth == 8) {
    for (std::size_t i = 0; i < image.samples.size(); ++i) image.samples[i] = bytes[i];
  } else {
    for (std::size_t i = 0; i < image.samples.size(); ++i) {
      image.samples[i] = static_cast<std::uint16_t>((bytes[2 * i] << 8U) | bytes[2 * i + 1]);
    }
  }
  return image;
}

}  // namespace

Result<PngImage> read_png(const std::filesystem::path& path) {
  PngIo io;
  try {
    io.file = std::fopen(path.c_str(), "rb");
    if (io.file == nullptr) {
      return io_error(std::string("cannot read '")
                          .append(path.string())
                          .append("': ")
                          .append(errno_message(errno)));
    }
    Result<PngImage> result = read_opened(io, path);
    std::fclose(io.file);
    return result;
  } catch (const std::exception& e) {  // out of memory
    if (io.file != nullptr) std::fclose(io.file);
    return io_error(
        std::string("cannot read '").append(path.string()).append("': ").append(e.what()));
  }
}

}  // namespace ocean::io
