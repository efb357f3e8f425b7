// The motion-vector picture of `ocean render --motion-vectors FILE.png` (docs/rendering.md
// R.26): each pixel's screen motion since the previous frame as a colour.
#pragma once

#include <filesystem>
#include <vector>

#include "ocean/core.hpp"

namespace ocean::cli {

/// Writes `xy` (Renderer::read_motion: width·height (dx, dy) pixels, rows down) as an RGB PNG:
/// red = 0.5 + 0.5·dx/s, green = 0.5 + 0.5·dy/s, blue 0.5 (grey: still; red right, green down),
/// s the 99th percentile of |motion| (at least 0.01 px), clamped to [0, 1]. Returns s.
Result<double> write_motion_png(const std::filesystem::path& path, int width, int height,
                                const std::vector<float>& xy);

}  // namespace ocean::cli
