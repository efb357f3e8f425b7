// src/io/exr_writer.cpp — OpenEXR writing through an fd-backed stream (atomic, errors checked).
#include <ImfChannelList.h>
#include <ImfCompression.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfIO.h>
#include <ImfOutputFile.h>
#include <fcntl.h>
#include <half.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdint>
#include <exception>
#include <set>
#include <string>
#include <system_error>
#include <vector>

#include "format_detail.hpp"
#include "ocean/io.hpp"

namespace ocean::io {
namespace {

using detail::failure;
using detail::FdGuard;
using detail::with_path;

// An OpenEXR output stream on a file descriptor that remembers the first write error, because
// OutputFile's destructor (which writes the line offset table) swallows exceptions.
class FdOStream final : public Imf::OStream {
 public:
  FdOStream(const char* file_name, int fd) : Imf::OStream(file_name), fd_(fd) {}

  void write(const char c[], int n) override {
    if (error_ != 0) throw std::system_error(error_, std::system_category(), "write failed");
    auto left = static_cast<std::size_t>(std::max(n, 0));
    while (left > 0) {
      const ssize_t w = ::pwrite(fd_, c, left, static_cast<off_t>(pos_));
      if (w < 0) {
        if (errno == EINTR) continue;
        error_ = errno;
        throw std::system_error(error_, std::system_category(), "write failed");
      }
      c += w;
      left -= static_cast<std::size_t>(w);
      pos_ += static_cast<std::uint64_t>(w);
    }
  }
  std::uint64_t tellp() override { return pos_; }
  void seekp(std::uint64_t pos) override { pos_ = pos; }
  [[nodiscard]] int error() const { return error_; }

 private:
  int fd_;
  std::uint64_t pos_ = 0;
  int error_ = 0;
};

Status validate(int width, int height, std::span<const ExrChannel> channels) {
  if (width < 1 || width > kExrMaxDimension || height < 1 || height > kExrMaxDimension) {
    return invalid_argument("EXR size " + std::to_string(width) + "x" + std::to_string(height) +
                            " is out of range: width and height must be in [1, " +
                            std::to_string(kExrMaxDimension) + "]");
  }
  if (channels.empty() || channels.size() > static_cast<std::size_t>(kExrMaxChannels)) {
    return invalid_argument("EXR image has " + std::to_string(channels.size()) +
                            " channels: needs 1 to " + std::to_string(kExrMaxChannels));
  }
  std::set<std::string> names;
  for (const ExrChannel& c : channels) {
    if (c.name.empty() || c.name.size() > 255 || c.name.find('\0') != std::string::npos) {
      return invalid_argument("EXR channel name '" + c.name +
                              "' is invalid: must be 1 to 255 bytes without NUL");
    }
    if (!names.insert(c.name).second) {
      return invalid_argument("EXR channel name '" + c.name + "' is used twice");
    }
    if (c.data == nullptr) {
      return invalid_argument("EXR channel '" + c.name + "' has no data (null pointer)");
    }
  }
  return Status::ok_status();
}

// Writes the whole file to `temporary`; the reason of a failure is the returned message.
Status write_to(const std::filesystem::path& temporary, int width, int height,
                std::span<const ExrChannel> channels, ExrPixelType type) {
  FdGuard guard;
  do {
    guard.fd = ::open(temporary.c_str(), O_WRONLY | O_TRUNC | O_CLOEXEC);
  } while (guard.fd < 0 && errno == EINTR);
  if (guard.fd < 0) return io_error(errno_message(errno));
  FdOStream stream(temporary.c_str(), guard.fd);
  try {
    Imf::Header header(width, height);
    header.compression() = Imf::ZIP_COMPRESSION;
    const Imf::PixelType file_type = type == ExrPixelType::half ? Imf::HALF : Imf::FLOAT;
    Imf::FrameBuffer frame_buffer;
    const auto pixels = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
    // OutputFile does not convert between pixel types, so half channels get a converted copy.
    std::vector<std::vector<half>> halves(type == ExrPixelType::half ? channels.size() : 0);
    for (std::size_t i = 0; i < channels.size(); ++i) {
      const ExrChannel& c = channels[i];
      header.channels().insert(c.name, Imf::Channel(file_type));
      if (type == ExrPixelType::half) {
        halves[i].assign(c.data, c.data + pixels);  // rounds to nearest; overflow to infinity
        frame_buffer.insert(
            c.name, Imf::Slice::Make(Imf::HALF, halves[i].data(), header.dataWindow(), sizeof(half),
                                     sizeof(half) * static_cast<std::size_t>(width)));
      } else {
        frame_buffer.insert(c.name,
                            Imf::Slice::Make(Imf::FLOAT, c.data, header.dataWindow(), sizeof(float),
                                             sizeof(float) * static_cast<std::size_t>(width)));
      }
    }
    Imf::OutputFile file(stream, header);
    file.setFrameBuffer(frame_buffer);
    file.writePixels(height);
  } catch (const std::exception& e) {
    if (stream.error() != 0) return io_error(errno_message(stream.error()));
    return io_error(e.what());
  }
  if (stream.error() != 0) return io_error(errno_message(stream.error()));
  if (const int err = guard.close_now(); err != 0) return io_error(errno_message(err));
  return Status::ok_status();
}

}  // namespace

Status write_exr(const std::filesystem::path& path, int width, int height,
                 std::span<const ExrChannel> channels, ExrPixelType type) {
  try {
    if (Status s = validate(width, height, channels); !s.ok()) return s;
    return write_atomically(path, [&](const std::filesystem::path& temporary) {
      return write_to(temporary, width, height, channels, type);
    });
  } catch (const std::exception& e) {
    return failure("write", path, e.what());
  } catch (...) {
    return failure("write", path, "unknown exception");
  }
}

}  // namespace ocean::io
