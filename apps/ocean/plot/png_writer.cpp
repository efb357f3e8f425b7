// PNG output for the plot module: libpng encoding in memory, then an atomic write-fsync-rename.
#include <fcntl.h>
#include <png.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <string>
#include <system_error>
#include <vector>

#include "plot_internal.hpp"

namespace ocean::plot {
namespace {

std::string errno_text(int err) { return std::system_category().message(err); }

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

// Writes all bytes, retrying on EINTR and short writes; returns 0 or an errno value.
int write_all(int fd, const unsigned char* data, std::size_t n) {
  while (n > 0) {
    const ssize_t w = ::write(fd, data, n);
    if (w < 0) {
      if (errno == EINTR) continue;
      return errno;
    }
    data += w;
    n -= static_cast<std::size_t>(w);
  }
  return 0;
}

// Temporary in the target's directory, fsync, rename over the target, fsync the directory.
Status write_atomically(const std::filesystem::path& path,
                        const std::vector<unsigned char>& bytes) {
  const std::filesystem::path dir = path.has_parent_path() ? path.parent_path() : ".";
  // Built with append rather than operator+ to dodge a g++ 12 -O3 -Wrestrict false positive.
  std::string leaf(1, '.');
  leaf.append(path.filename().string()).append(".tmp-XXXXXX");
  const std::string tmpl = (dir / leaf).string();
  std::vector<char> name(tmpl.begin(), tmpl.end());
  name.push_back('\0');
  const int fd = ::mkstemp(name.data());
  if (fd < 0) return write_error(path, errno_text(errno));
  const auto fail = [&](int err, const std::string& what) {
    ::unlink(name.data());
    return write_error(path, what + errno_text(err));
  };
  if (int err = write_all(fd, bytes.data(), bytes.size()); err != 0) {
    ::close(fd);
    return fail(err, "");
  }
  // mkstemp creates 0600; a plot should be readable like any other output file. (Reading the
  // umask would mean changing it, which races with other threads.)
  if (::fchmod(fd, static_cast<mode_t>(0644)) != 0) {
    const int err = errno;
    ::close(fd);
    return fail(err, "cannot set permissions: ");
  }
  if (::fsync(fd) != 0) {
    const int err = errno;
    ::close(fd);
    return fail(err, "fsync failed: ");
  }
  if (::close(fd) != 0) return fail(errno, "close failed: ");
  if (::rename(name.data(), path.c_str()) != 0) return fail(errno, "");
  // Make the rename itself durable; failure here does not undo a complete write.
  if (const int dfd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC); dfd >= 0) {
    (void)::fsync(dfd);
    ::close(dfd);
  }
  return Status::ok_status();
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
    return write_atomically(path, bytes.value());
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
