// world_grid.hpp: the checks and the copy the renderer's world grids share.
#include "world_grid.hpp"

#include <cmath>
#include <string>

namespace ocean::render {

Status check_world_grid(std::string_view what, const std::array<double, 2>& origin_m, double size_m,
                        int resolution) {
  const std::string prefix(what);
  if (resolution < 1 || resolution > kMaxWorldGridSide)
    return invalid_argument(prefix + ": resolution = " + std::to_string(resolution) +
                            " must be in [1, " + std::to_string(kMaxWorldGridSide) + "]");
  if (!std::isfinite(size_m) || !(size_m > 0.0) || !std::isfinite(origin_m[0]) ||
      !std::isfinite(origin_m[1]))
    return invalid_argument(prefix + ": the area (origin and size) must be finite, size > 0");
  return {};
}

void record_world_grid_upload(VkCommandBuffer cmd, VkBuffer staging, VkImage image,
                              std::uint32_t side, std::uint32_t layers) {
  const VkPipelineStageFlags shaders =
      VK_PIPELINE_STAGE_VERTEX_SHADER_BIT | VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT;
  vk::image_barrier(cmd, image, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_GENERAL, shaders, 0,
                    VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT);
  const VkBufferImageCopy region{.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, layers},
                                 .imageExtent = {side, side, 1}};
  vkCmdCopyBufferToImage(cmd, staging, image, VK_IMAGE_LAYOUT_GENERAL, 1, &region);
  vk::barrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, shaders);
}

}  // namespace ocean::render
