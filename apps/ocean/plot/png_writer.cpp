// PNG output for the plot module: libpng encoding in memory, then an atomic write (io module).
#include <png.h>

#include <cstddef>
#include <exception>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include "io/atomic_file.hpp"
#include "plot_internal.hpp"

namespace ocean::plot {
namespace {

Status write_error(const std::filesystem::path& path, const std::string& reason) {
  return io_error("cannot write '" + path.string() + "': " + reason);
}

Result<std::vector<unsigned char>> encode_png(const Image& image,
                                              const std::filesystem::path& path) {
  png_image pi{};
  pi.version = PNG_IMAGE_VERSION;
  pi.width = static_cast<png_uint_32>(image.width);
  pi.height = static_cast<png_uint_32>(image.height);
  pi.format = PNG_FORMAT_RGB;
  png_alloc_size_t size = 0;
  // First pass measures, second pass writes.
  if (png_image_write_to_memory(&pi, nullptr, &size, 0, image.rgb.data(), 0, nullptr) == 0) {
    const std::string msg = pi.message;
    png_image_free(&pi);
    return write_error(path, "PNG encoding failed: " + msg);
  }
  std::vector<unsigned char> buf(size);
  if (png_image_write_to_memory(&pi, buf.data(), &size, 0, image.rgb.data(), 0, nullptr) == 0) {
    const std::string msg = pi.message;
    png_image_free(&pi);
    return write_error(path, "PNG encoding failed: " + msg);
  }
  buf.resize(size);
  return buf;
}

}  // namespace

Status write_png(const Image& image, const std::filesystem::path& path) {
  try {
    if (image.width <= 0 || image.height <= 0 ||
        image.rgb.size() !=
            static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height) * 3U) {
      return invalid_argument("image is " + std::to_string(image.width) + "x" +
                              std::to_string(image.height) + " with " +
                              std::to_string(image.rgb.size()) +
                              " bytes: needs positive sizes and width*height*3 bytes");
    }
    if (path.empty() || !path.has_filename()) {
      return invalid_argument("PNG path '" + path.string() + "' must name a file");
    }
    Result<std::vector<unsigned char>> bytes = encode_png(image, path);
    if (!bytes.ok()) return bytes.status();
    return io::write_bytes_atomically(path, {std::as_bytes(std::span(bytes.value()))});
  } catch (const std::exception& e) {
    return write_error(path, e.what());
  }
}

Status write_png(const Figure& figure, const std::filesystem::path& path) {
  Result<Image> image = render(figure);
  if (!image.ok()) return image.status();
  return write_png(image.value(), path);
}

}  // namespace ocean::plot
