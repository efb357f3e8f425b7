// What the renderer's host-filled world grids share (the local layer, local_layer.cpp; the
// damping, damping.cpp): the check of a grid's placement and side, and the copy of its staging
// buffer into its image before the frame's draws.
#pragma once

#include <array>
#include <cstdint>
#include <string_view>

#include "ocean/core.hpp"
#include "ocean/vk.hpp"

namespace ocean::render {

/// The largest side of a world grid, cells.
inline constexpr int kMaxWorldGridSide = 4096;

/// invalid_argument "<what>: resolution = N must be in [1, 4096]" or "<what>: the area (origin
/// and size) must be finite, size > 0".
Status check_world_grid(std::string_view what, const std::array<double, 2>& origin_m, double size_m,
                        int resolution);

/// Records the copy of `staging` (layers side × side images, tightly packed) into `image`
/// (GENERAL), between the vertex and fragment shaders' reads of the frame before and after.
void record_world_grid_upload(VkCommandBuffer cmd, VkBuffer staging, VkImage image,
                              std::uint32_t side, std::uint32_t layers);

}  // namespace ocean::render
