// tests/support/exr_reader.cpp — reads every channel of an OpenEXR file as floats.
#include "support/exr_reader.hpp"

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdint>
#include <exception>
#include <string>
#include <vector>

#include "io/format_detail.hpp"
#include "ocean/io.hpp"

namespace ocean::io {
namespace {

using detail::failure;
using detail::FdGuard;
using detail::with_path;

// Checks that the file can be opened and starts with the OpenEXR magic number.
Status check_magic(const std::filesystem::path& path) {
  FdGuard guard;
  do {
    guard.fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  } while (guard.fd < 0 && errno == EINTR);
  if (guard.fd < 0) return io_error(with_path("read", path, errno_message(errno)));
  unsigned char magic[4] = {};
  ssize_t got = 0;
  do {
    got = ::read(guard.fd, magic, sizeof magic);
  } while (got < 0 && errno == EINTR);
  if (got < 0) return io_error(with_path("read", path, errno_message(errno)));
  if (got != 4 || magic[0] != 0x76 || magic[1] != 0x2f || magic[2] != 0x31 || magic[3] != 0x01) {
    return io_error(with_path("read", path, "not an OpenEXR file (wrong magic)"));
  }
  return Status::ok_status();
}

Result<ExrImage> read_checked(const std::filesystem::path& path) {
  Imf::InputFile file(path.c_str());
  const Imf::Header& header = file.header();
  const Imath::Box2i window = header.dataWindow();
  const std::int64_t w = std::int64_t{window.max.x} - window.min.x + 1;
  const std::int64_t h = std::int64_t{window.max.y} - window.min.y + 1;
  if (w < 1 || w > kExrMaxDimension || h < 1 || h > kExrMaxDimension) {
    return io_error(with_path("read", path,
                              "data window " + std::to_string(w) + "x" + std::to_string(h) +
                                  " is out of range [1, " + std::to_string(kExrMaxDimension) +
                                  "]"));
  }
  ExrImage image;
  image.width = static_cast<int>(w);
  image.height = static_cast<int>(h);
  for (auto it = header.channels().begin(); it != header.channels().end(); ++it) {
    const Imf::Channel& channel = it.channel();
    const std::string name = it.name();
    if (channel.xSampling != 1 || channel.ySampling != 1) {
      return io_error(with_path("read", path, "channel '" + name + "' is subsampled"));
    }
    if (channel.type != Imf::HALF && channel.type != Imf::FLOAT) {
      return io_error(with_path(
          "read", path, "channel '" + name + "' is not HALF or FLOAT (UINT is unsupported)"));
    }
    if (image.channel_names.size() == static_cast<std::size_t>(kExrMaxChannels)) {
      return io_error(
          with_path("read", path, "more than " + std::to_string(kExrMaxChannels) + " channels"));
    }
    image.channel_names.push_back(name);
    image.pixel_types.push_back(channel.type == Imf::HALF ? ExrPixelType::half
                                                          : ExrPixelType::float32);
  }
  if (image.channel_names.empty()) return io_error(with_path("read", path, "no channels"));
  image.planes.resize(image.channel_names.size());
  Imf::FrameBuffer frame_buffer;
  for (std::size_t i = 0; i < image.planes.size(); ++i) {
    image.planes[i].assign(static_cast<std::size_t>(w * h), 0.0f);
    frame_buffer.insert(image.channel_names[i],
                        Imf::Slice::Make(Imf::FLOAT, image.planes[i].data(), window, sizeof(float),
                                         sizeof(float) * static_cast<std::size_t>(w)));
  }
  file.setFrameBuffer(frame_buffer);
  file.readPixels(window.min.y, window.max.y);
  return image;
}

}  // namespace

Result<ExrImage> read_exr(const std::filesystem::path& path) {
  try {
    if (Status s = check_magic(path); !s.ok()) return s;
    return read_checked(path);
  } catch (const std::exception& e) {
    return failure("read", path, e.what());
  } catch (...) {
    return failure("read", path, "unknown exception");
  }
}

}  // namespace ocean::io
