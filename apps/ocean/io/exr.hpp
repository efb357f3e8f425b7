// io/exr.hpp — OpenEXR scanline images (ZIP compressed, half or float channels): writer and reader.
#pragma once

#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include "ocean/core.hpp"

namespace ocean::io {

/// Largest width or height write_exr and read_exr accept.
inline constexpr int kExrMaxDimension = 16384;
/// Largest number of channels write_exr and read_exr accept.
inline constexpr int kExrMaxChannels = 1024;

/// How samples are stored in the file (values are always passed as float).
enum class ExrPixelType { half, float32 };

/// One channel to write: `data` points to width*height floats, row-major, row 0 the top row.
struct ExrChannel {
  std::string name;
  const float* data = nullptr;
};

/// An image read back: one plane of width*height floats (row-major, row 0 on top) per channel.
/// Channels come in the file's order, which OpenEXR sorts by name.
struct ExrImage {
  int width = 0;
  int height = 0;
  std::vector<std::string> channel_names;
  std::vector<ExrPixelType> pixel_types;
  std::vector<std::vector<float>> planes;
};

/// Writes a single-part scanline OpenEXR file with ZIP compression; every channel has the same
/// pixel `type`. Data window and display window are (0,0)-(width-1,height-1), line order
/// increasing y, so row 0 of each channel is the top row of the image.
///
/// Contract:
///  - invalid_argument (nothing written) unless 1 <= width, height <= kExrMaxDimension, there are
///    1..kExrMaxChannels channels, each with non-null data and a unique, non-empty name of at most
///    255 bytes without NUL characters.
///  - float32 stores values bit-exactly. half rounds to nearest; magnitudes beyond 65504 become
///    infinities, NaN stays NaN.
///  - Written atomically (see write_atomically): on failure `path` keeps its old contents and
///    the result is io_error "cannot write '<path>': <reason>". Write errors that OpenEXR would
///    swallow while finishing the file are detected too. Never throws.
ocean::Status write_exr(const std::filesystem::path& path, int width, int height,
                        std::span<const ExrChannel> channels, ExrPixelType type);

/// Reads every channel of an OpenEXR file (scanline or tiled, any compression) as floats.
///
/// Contract: of a multi-part file only the first part is read. io_error "cannot read '<path>':
/// <reason>" if the file cannot be opened, is not an OpenEXR file, is corrupt or truncated, is a
/// deep image, has subsampled or UINT channels, a data window larger than kExrMaxDimension in
/// either direction, or more than kExrMaxChannels channels. Never throws (OpenEXR exceptions
/// become io_error).
ocean::Result<ExrImage> read_exr(const std::filesystem::path& path);

}  // namespace ocean::io
