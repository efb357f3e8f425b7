// tests/support/png_reader.hpp — the PNG reader the tests check written files with.
#pragma once

#include <cstdint>
#include <filesystem>
#include <vector>

#include "ocean/io.hpp"

namespace ocean::io {

/// A PNG image read back: samples of row 0 (the top row) first, channels interleaved.
struct PngImage {
  int width = 0;
  int height = 0;
  int channels = 0;                    ///< 1 gray, 2 gray+alpha, 3 RGB, 4 RGBA
  int bit_depth = 0;                   ///< 8 or 16: the depth of `samples` (see read_png)
  std::vector<std::uint16_t> samples;  ///< width*height*channels values, 0..2^bit_depth-1
};

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
