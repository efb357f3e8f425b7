// What `ocean render` and `ocean view` write and report about a rendered picture: the sRGB PNG
// and the validation layer's verdict. The scene they draw is the library's (ocean/scene.hpp).
#pragma once

#include <cstdint>
#include <filesystem>
#include <string_view>
#include <vector>

#include "ocean/core.hpp"
#include "ocean/vk.hpp"

namespace ocean::cli {

/// What `ocean render` holds for each pixel of a picture while writing it, beside the renderer's
/// read-back buffer: for a PNG the sRGB pixels (4 bytes) and their RGB copy (3); for an EXR the
/// float pixels (16), their planes (12) and the half copies the writer makes (6); for a video
/// frame the sRGB pixels (4); for a contact sheet, per pixel of a tile, the sRGB pixels (4), the
/// nine RGB tiles (27) and the sheet they are copied into (27, margins and title aside).
inline constexpr std::uint64_t kPngBytesPerPixel = 7;
inline constexpr std::uint64_t kExrBytesPerPixel = 34;
inline constexpr std::uint64_t kVideoBytesPerPixel = 4;
inline constexpr std::uint64_t kSheetBytesPerTilePixel = 58;

/// Refuses, before anything is allocated, a picture this machine cannot hold: the renderer's
/// read-back buffer and `bytes_per_pixel` for each pixel, against memory_budget()
/// (ocean/memory_budget.hpp). invalid_argument "--width <w> --height <h>: rendering <what> needs
/// 3.8 GiB of memory, more than the 2.0 GiB the address-space limit (ulimit -v) leaves".
Status check_picture_memory(int width, int height, std::uint64_t bytes_per_pixel,
                            std::string_view what);

/// The renderer's sRGB pixels (RGBA8, alpha opaque) as an RGB PNG, written atomically.
Status write_srgb_png(const std::filesystem::path& path, int width, int height,
                      const std::vector<std::uint8_t>& rgba);

/// ok unless the context runs the validation layer and it reported something: then one line
/// with the count and the last message (`--validation` fails on any message).
Status validation_status(const vk::Context& context);

}  // namespace ocean::cli
