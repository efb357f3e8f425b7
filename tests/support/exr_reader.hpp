// tests/support/exr_reader.hpp — the OpenEXR reader the tests check written files with.
#pragma once

#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include "ocean/io.hpp"

namespace ocean::io {

/// An image read back: one plane of width*height floats (row-major, row 0 on top) per channel.
/// Channels come in the file's order, which OpenEXR sorts by name.
struct ExrImage {
  int width = 0;
  int height = 0;
  std::vector<std::string> channel_names;
  std::vector<ExrPixelType> pixel_types;
  std::vector<std::vector<float>> planes;
};

/// Reads every channel of an OpenEXR file (scanline or tiled, any compression) as floats.
///
/// Contract: of a multi-part file only the first part is read. io_error "cannot read '<path>':
/// <reason>" if the file cannot be opened, is not an OpenEXR file, is corrupt or truncated, is a
/// deep image, has subsampled or UINT channels, a data window larger than kExrMaxDimension in
/// either direction, more than kExrMaxChannels channels, or needs more than 1 GiB of samples as
/// floats. The header is checked first (see exr_header.hpp: every attribute inside the file and
/// read by OpenEXR as its declared size), then the data window and the sample budget, before
/// OpenEXR reads the file and sizes its buffers from them. The pixels are read in blocks of rows,
/// so memory grows with the rows the file holds rather than with the size it declares. The file
/// is read whole once for the header check. Never throws (OpenEXR exceptions become io_error).
ocean::Result<ExrImage> read_exr(const std::filesystem::path& path);

}  // namespace ocean::io
