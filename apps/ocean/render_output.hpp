// What `ocean render` and `ocean view` write and report about a rendered picture: the sRGB PNG
// and the validation layer's verdict. The scene they draw is the library's (ocean/scene.hpp).
#pragma once

#include <cstdint>
#include <filesystem>
#include <vector>

#include "ocean/core.hpp"
#include "ocean/vk.hpp"

namespace ocean::cli {

/// The renderer's sRGB pixels (RGBA8, alpha opaque) as an RGB PNG, written atomically.
Status write_srgb_png(const std::filesystem::path& path, int width, int height,
                      const std::vector<std::uint8_t>& rgba);

/// ok unless the context runs the validation layer and it reported something: then one line
/// with the count and the last message (`--validation` fails on any message).
Status validation_status(const vk::Context& context);

}  // namespace ocean::cli
