// io/png_image.hpp — PNG images from raw samples (8-bit 1–4 channels, 16-bit gray) and a reader.
#pragma once

#include <cstdint>
#include <filesystem>
#include <vector>

#include "ocean/core.hpp"

namespace ocean::io {

/// Largest width or height the PNG writers and reader accept (libpng's default user limit).
inline constexpr int kPngMaxDimension = 1000000;

/// A PNG image read back: samples of row 0 (the top row) first, channels interleaved.
struct PngImage {
  int width = 0;
  int height = 0;
  int channels = 0;                    ///< 1 gray, 2 gray+alpha, 3 RGB, 4 RGBA
  int bit_depth = 0;                   ///< 8 or 16: the depth of `samples` (see read_png)
  std::vector<std::uint16_t> samples;  ///< width*height*channels values, 0..2^bit_depth-1
};

/// Writes an 8-bit PNG: `channels` 1 = gray, 2 = gray+alpha, 3 = RGB, 4 = RGBA.
///
/// Contract:
///  - `pixels` holds width*height*channels bytes, rows top to bottom, channels interleaved
///    (alpha not premultiplied). Samples are stored exactly; no gamma or colour-space chunk is
///    written, no filtering of values.
///  - invalid_argument (nothing written) unless 1 <= width, height <= kPngMaxDimension, channels
///    is 1..4, `pixels` is non-null and the byte size does not overflow.
///  - Written atomically (see write_atomically); io_error "cannot write '<path>': <reason>" on
///    failure, leaving `path` as it was. Never throws.
ocean::Status write_png8(const std::filesystem::path& path, int width, int height, int channels,
                         const std::uint8_t* pixels);

/// Writes a 16-bit grayscale PNG from native-endian samples (stored big-endian in the file, as
/// PNG requires); otherwise the same contract as write_png8 with channels = 1.
ocean::Status write_png16_gray(const std::filesystem::path& path, int width, int height,
                               const std::uint16_t* pixels);

/// Reads any non-interlaced or interlaced PNG and returns its samples without colour or gamma
/// conversion.
///
/// Contract: palette images become RGB (RGBA with a tRNS chunk); grayscale of 1, 2 or 4 bits is
/// scaled to 8 bits; a tRNS chunk on a gray or RGB image adds an alpha channel; 8- and 16-bit
/// samples are returned as stored. io_error "cannot read '<path>': <reason>" if the file cannot be
/// opened or is not a valid PNG (wrong signature, bad CRC, truncated, corrupt data), or if it is
/// larger than kPngMaxDimension in either direction or needs more than 1 GiB of samples. Never
/// throws; safe on arbitrary bytes.
ocean::Result<PngImage> read_png(const std::filesystem::path& path);

}  // namespace ocean::io
