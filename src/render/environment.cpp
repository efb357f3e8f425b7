// The HDR environment map on the device (docs/rendering.md R.17; environment_map.cpp reads the
// file): uploaded as an RGBA32F image the shaders read instead of the analytic sky's table
// (background, reflections, fog), and its irradiance on a horizontal plane, which lights the water
// body and the foam in place of the analytic sky's.
//
// Sources: Paleologue 2024 (the skybox the water reflects); Mitchell 2005 (the environment term
// of the composition); Blinn & Newell 1976 (reflection mapping by a latitude–longitude map).
#include <cmath>
#include <cstring>
#include <numbers>

#include "sky_pass.hpp"
#include "state.hpp"

namespace ocean::render {

namespace {

// ∫ L cosθ dω over the upper hemisphere, texel by texel: a row at elevation e spans the solid
// angle (2π/width)·(π/height)·cos e per texel and sees the plane at cosθ = sin e.
std::array<double, 3> irradiance(const Environment& e) {
  std::array<double, 3> sum{};
  const double d_azimuth = 2.0 * std::numbers::pi / e.width;
  const double d_elevation = std::numbers::pi / e.height;
  for (int y = 0; y < e.height / 2; ++y) {
    const double elevation = 0.5 * std::numbers::pi - (y + 0.5) * d_elevation;
    const double w = d_azimuth * d_elevation * std::cos(elevation) * std::sin(elevation);
    for (int x = 0; x < e.width; ++x)
      for (std::size_t c = 0; c < 3; ++c)
        sum[c] += w * e.rgb[(static_cast<std::size_t>(y) * e.width + x) * 3 + c];
  }
  return sum;
}

}  // namespace

Status Renderer::set_environment(const Environment* environment) {
  State& st = *state_;
  const Environment black{.width = 1, .height = 1, .rgb = {0.0f, 0.0f, 0.0f}};
  const Environment& e = environment != nullptr ? *environment : black;
  const auto texels = static_cast<std::size_t>(e.width) * static_cast<std::size_t>(e.height);
  if (e.width < 1 || e.height < 1 || e.rgb.size() != texels * 3)
    return invalid_argument("environment: " + std::to_string(e.rgb.size()) + " values for a " +
                            std::to_string(e.width) + "x" + std::to_string(e.height) +
                            " map (3 per texel)");
  Result<vk::Buffer> staging = vk::create_buffer(
      *st.ctx, texels * 4 * sizeof(float), VK_BUFFER_USAGE_TRANSFER_SRC_BIT, vk::MemoryUse::upload);
  if (!staging.ok()) return staging.status();
  vk::Buffer buffer = staging.value();
  auto* rgba = static_cast<float*>(buffer.mapped);
  for (std::size_t p = 0; p < texels; ++p) {
    std::memcpy(rgba + 4 * p, e.rgb.data() + 3 * p, 3 * sizeof(float));
    rgba[4 * p + 3] = 1.0f;
  }
  SkyPass& sky = pass<SkyPass>(st);
  vkDeviceWaitIdle(st.ctx->device);
  vk::destroy_image(*st.ctx, sky.environment);
  Result<vk::Image2D> image =
      vk::create_image_2d(*st.ctx, VK_FORMAT_R32G32B32A32_SFLOAT,
                          static_cast<std::uint32_t>(e.width), static_cast<std::uint32_t>(e.height),
                          VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT);
  if (!image.ok()) {
    vk::destroy_buffer(*st.ctx, buffer);
    return image.status();
  }
  sky.environment = image.value();
  const Status copied = vk::run_once(*st.ctx, st.commands, [&](VkCommandBuffer cmd) {
    vk::image_barrier(cmd, sky.environment.image, VK_IMAGE_LAYOUT_UNDEFINED,
                      VK_IMAGE_LAYOUT_GENERAL, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, 0,
                      VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT);
    const VkBufferImageCopy region{.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1},
                                   .imageExtent = {static_cast<std::uint32_t>(e.width),
                                                   static_cast<std::uint32_t>(e.height), 1}};
    vkCmdCopyBufferToImage(cmd, buffer.buffer, sky.environment.image, VK_IMAGE_LAYOUT_GENERAL, 1,
                           &region);
    vk::barrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT);
  });
  vk::destroy_buffer(*st.ctx, buffer);
  if (!copied.ok()) return copied;
  sky.has_environment = environment != nullptr;
  sky.environment_irradiance = irradiance(e);
  write_scene_images(st);
  return {};
}

}  // namespace ocean::render
