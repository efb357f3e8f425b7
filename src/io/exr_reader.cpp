// Reads every channel of an OpenEXR file as floats, after checking its header for sizes that
// would make OpenEXR allocate more than the file holds (exr_header.cpp).

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <sys/stat.h>

#include <algorithm>
#include <cerrno>
#include <cstdint>
#include <exception>
#include <string>
#include <utility>
#include <vector>

#include "exr_header.hpp"
#include "format_detail.hpp"
#include "ocean/io.hpp"

namespace ocean::io {
namespace {

using detail::failure;
using detail::with_path;

// Reads the whole file into `bytes`, under kExrMaxFileBytes: what is not a regular file
// (/dev/zero, a FIFO that would block) and a file over the limit are refused before a byte is
// read; read_bounded then holds the read to the limit should the file grow meanwhile.
Status read_all(const std::filesystem::path& path, std::string& bytes) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0)
    return io_error(with_path("read", path, errno_message(errno)));
  const std::string limit = byte_limit_text(kExrMaxFileBytes);
  if (!S_ISREG(st.st_mode)) {
    return io_error(with_path("read", path,
                              std::string("it is ") + detail::file_kind(st.st_mode) +
                                  ", not a regular file; an OpenEXR file is read whole, at most " +
                                  limit));
  }
  if (static_cast<std::uint64_t>(st.st_size) > kExrMaxFileBytes) {
    return io_error(with_path("read", path,
                              "it holds " + std::to_string(st.st_size) + " bytes, more than the " +
                                  limit + " an OpenEXR file may hold"));
  }
  Result<std::string> read = read_bounded(
      path, {.max_bytes = kExrMaxFileBytes, .what = "OpenEXR file", .regular_only = true});
  if (!read.ok()) return io_error(read.status().message());
  bytes = std::move(read).value();
  return Status::ok_status();
}

// The most sample bytes (as floats) the reader holds, as the PNG reader.
constexpr std::uint64_t kMaxSampleBytes = std::uint64_t{1} << 30;
// Rows read per readPixels call: the planes grow by a block at a time.
constexpr std::int64_t kRowsPerBlock = 256;

// The data window's size and the sample budget, checked on the header walk's numbers before
// OpenEXR sizes its buffers from them, and again on OpenEXR's header.
Status check_size(const std::filesystem::path& path, std::int64_t w, std::int64_t h,
                  std::size_t channels) {
  if (w < 1 || w > kExrMaxDimension || h < 1 || h > kExrMaxDimension) {
    return io_error(with_path("read", path,
                              "data window " + std::to_string(w) + "x" + std::to_string(h) +
                                  " is out of range [1, " + std::to_string(kExrMaxDimension) +
                                  "]"));
  }
  if (static_cast<std::uint64_t>(w * h) * channels * sizeof(float) > kMaxSampleBytes)
    return io_error(
        with_path("read", path, "image is too large to read (more than 1 GiB of samples)"));
  return Status::ok_status();
}

// OpenEXR reads a tiled file through a buffer of whole tiles: a row of tiles across the data
// window, tile_height rows high, and one tile. A header may declare tiles of 2^31 pixels on an
// 8×8 image; both buffers are held to the sample budget before OpenEXR sizes them.
Status check_tiles(const std::filesystem::path& path, const ExrHeaderInfo& info) {
  if (info.tile_width == 0 && info.tile_height == 0) return Status::ok_status();
  const auto refuse = [&] {
    return io_error(with_path("read", path,
                              "tiles of " + std::to_string(info.tile_width) + "x" +
                                  std::to_string(info.tile_height) +
                                  " would need more than 1 GiB of samples to read"));
  };
  if (info.tile_width < 1 || info.tile_height < 1 || info.tile_width > kExrMaxDimension ||
      info.tile_height > kExrMaxDimension)
    return refuse();
  const auto bytes_per_pixel = static_cast<std::uint64_t>(info.channels) * sizeof(float);
  const std::uint64_t across =
      static_cast<std::uint64_t>(std::max(info.width, info.tile_width) * info.tile_height);
  if (across * bytes_per_pixel > kMaxSampleBytes) return refuse();
  return Status::ok_status();
}

Status check_header(const std::filesystem::path& path) {
  std::string bytes;
  if (Status s = read_all(path, bytes); !s.ok()) return s;
  const ExrHeaderInfo info = check_exr_header(bytes);
  if (!info.problem.empty()) return io_error(with_path("read", path, info.problem));
  if (Status s = check_size(path, info.width, info.height, info.channels); !s.ok()) return s;
  return check_tiles(path, info);
}

Result<ExrImage> read_checked(const std::filesystem::path& path) {
  Imf::InputFile file(path.c_str());
  const Imf::Header& header = file.header();
  const Imath::Box2i window = header.dataWindow();
  const std::int64_t w = std::int64_t{window.max.x} - window.min.x + 1;
  const std::int64_t h = std::int64_t{window.max.y} - window.min.y + 1;
  ExrImage image;
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
  if (Status s = check_size(path, w, h, image.channel_names.size()); !s.ok()) return s;
  image.width = static_cast<int>(w);
  image.height = static_cast<int>(h);
  image.planes.resize(image.channel_names.size());
  // Block by block, each plane grown by the block's rows first: memory follows the rows the file
  // holds, not the size its header declares (a truncated file fails at its first block).
  const auto row = static_cast<std::size_t>(w);
  for (std::int64_t first = 0; first < h; first += kRowsPerBlock) {
    const std::int64_t last = std::min(h, first + kRowsPerBlock) - 1;
    const Imath::Box2i block({window.min.x, static_cast<int>(window.min.y + first)},
                             {window.max.x, static_cast<int>(window.min.y + last)});
    Imf::FrameBuffer frame_buffer;
    for (std::size_t i = 0; i < image.planes.size(); ++i) {
      image.planes[i].resize(static_cast<std::size_t>(last + 1) * row, 0.0f);
      frame_buffer.insert(
          image.channel_names[i],
          Imf::Slice::Make(Imf::FLOAT,
                           image.planes[i].data() + static_cast<std::size_t>(first) * row, block,
                           sizeof(float), sizeof(float) * row));
    }
    file.setFrameBuffer(frame_buffer);
    file.readPixels(block.min.y, block.max.y);
  }
  return image;
}

}  // namespace

Result<ExrImage> read_exr(const std::filesystem::path& path) {
  try {
    if (Status s = check_header(path); !s.ok()) return s;
    return read_checked(path);
  } catch (const std::exception& e) {
    return failure("read", path, e.what());
  } catch (...) {
    return failure("read", path, "unknown exception");
  }
}

}  // namespace ocean::io
