// The renderer's target formats and limits (src/render, private): what state.hpp's targets and
// pipeline_desc.hpp's attachments share, in a header that needs nothing of the state, so that a
// pass written whole in its header (pass.hpp) can build its pipelines.
#pragma once

#include <vulkan/vulkan.h>

#include "shaders/render_shared.h"

namespace ocean::render {

inline constexpr int kMaxCascades = OCEAN_RENDER_MAX_CASCADES;
inline constexpr VkFormat kHdrFormat = VK_FORMAT_R16G16B16A16_SFLOAT;
inline constexpr VkFormat kSrgbFormat = VK_FORMAT_R8G8B8A8_SRGB;
inline constexpr VkFormat kDepthFormat = VK_FORMAT_D32_SFLOAT;
inline constexpr int kMaxTargetSize = 16384;

}  // namespace ocean::render
