// The HDR environment map (docs/rendering.md R.17): an equirectangular OpenEXR image read with
// read_exr (ocean/io.hpp), halved to at most 2048 × 1024, uploaded as an RGBA32F image the
// shaders read instead of the analytic sky's table (background, reflections, fog), and its
// irradiance on a horizontal plane, which lights the water body and the foam in place of the
// analytic sky's.
//
// Sources: Paleologue 2024 (the skybox the water reflects); Mitchell 2005 (the environment term
// of the composition); Blinn & Newell 1976 (reflection mapping by a latitude–longitude map).
#include <cmath>
#include <cstring>
#include <numbers>

#include "ocean/io.hpp"
#include "state.hpp"

namespace ocean::render {

namespace {

constexpr int kMaxWidth = 2048;

// Halves both sides with a 2×2 box (w and h even).
Environment halve(const Environment& e) {
  Environment out{.width = e.width / 2, .height = e.height / 2, .rgb = {}};
  out.rgb.resize(static_cast<std::size_t>(out.width) * out.height * 3);
  const auto at = [&](int x, int y, int c) {
    return e.rgb[(static_cast<std::size_t>(y) * e.width + x) * 3 + c];
  };
  for (int y = 0; y < out.height; ++y)
    for (int x = 0; x < out.width; ++x)
      for (int c = 0; c < 3; ++c)
        out.rgb[(static_cast<std::size_t>(y) * out.width + x) * 3 + c] =
            0.25f * (at(2 * x, 2 * y, c) + at(2 * x + 1, 2 * y, c) + at(2 * x, 2 * y + 1, c) +
                     at(2 * x + 1, 2 * y + 1, c));
  return out;
}

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

Result<Environment> load_environment(const std::filesystem::path& path) {
  Result<io::ExrImage> read = io::read_exr(path);
  if (!read.ok()) return read.status();
  const io::ExrImage& image = read.value();
  const std::string name = "environment '" + excerpt(path.string()) + "'";
  std::array<const std::vector<float>*, 3> planes{};
  constexpr std::array<const char*, 3> kChannels = {"R", "G", "B"};
  for (std::size_t c = 0; c < 3; ++c) {
    for (std::size_t i = 0; i < image.channel_names.size(); ++i)
      if (image.channel_names[i] == kChannels[c]) planes[c] = &image.planes[i];
    if (planes[c] == nullptr)
      return invalid_argument(name + " has no channel " + kChannels[c] +
                              ": an environment map is an RGB OpenEXR image");
  }
  if (image.width != 2 * image.height || image.height < 2 || image.height % 2 != 0)
    return invalid_argument(name + " is " + std::to_string(image.width) + "x" +
                            std::to_string(image.height) +
                            ": an equirectangular map is twice as wide as high (an even height)");
  Environment e{.width = image.width, .height = image.height, .rgb = {}};
  e.rgb.resize(static_cast<std::size_t>(e.width) * e.height * 3);
  for (std::size_t p = 0; p < e.rgb.size() / 3; ++p) {
    for (std::size_t c = 0; c < 3; ++c) {
      const float v = (*planes[c])[p];
      if (!std::isfinite(v) || v < 0.0f)
        return invalid_argument(name + " holds a negative or non-finite radiance (" +
                                format_number(v) + "): it must be a linear HDR image");
      e.rgb[3 * p + c] = v;
    }
  }
  while (e.width > kMaxWidth && e.height % 2 == 0) e = halve(e);
  return e;
}

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
  vkDeviceWaitIdle(st.ctx->device);
  vk::destroy_image(*st.ctx, st.environment);
  Result<vk::Image2D> image =
      vk::create_image_2d(*st.ctx, VK_FORMAT_R32G32B32A32_SFLOAT,
                          static_cast<std::uint32_t>(e.width), static_cast<std::uint32_t>(e.height),
                          VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT);
  if (!image.ok()) {
    vk::destroy_buffer(*st.ctx, buffer);
    return image.status();
  }
  st.environment = image.value();
  const Status copied = vk::run_once(*st.ctx, st.commands, [&](VkCommandBuffer cmd) {
    vk::image_barrier(cmd, st.environment.image, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_GENERAL,
                      VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, 0, VK_PIPELINE_STAGE_TRANSFER_BIT,
                      VK_ACCESS_TRANSFER_WRITE_BIT);
    const VkBufferImageCopy region{.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1},
                                   .imageExtent = {static_cast<std::uint32_t>(e.width),
                                                   static_cast<std::uint32_t>(e.height), 1}};
    vkCmdCopyBufferToImage(cmd, buffer.buffer, st.environment.image, VK_IMAGE_LAYOUT_GENERAL, 1,
                           &region);
    vk::barrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT);
  });
  vk::destroy_buffer(*st.ctx, buffer);
  if (!copied.ok()) return copied;
  st.has_environment = environment != nullptr;
  st.environment_irradiance = irradiance(e);
  write_scene_images(st);
  return {};
}

void fill_environment_uniforms(const Renderer::State& st, const View& view,
                               shader::FrameUniforms& u) {
  if (!st.has_environment) {
    u.environment = {0.0f, 0.0f, 0.0f, 0.0f};
    return;
  }
  // The map's radiance scaled by sky_brightness; > 0 marks it in use (a scale of 0 would be the
  // black sky the analytic model gives for sky_brightness = 0 too).
  const double scale = view.shading.sky_brightness;
  u.environment = {static_cast<float>(std::max(scale, 1e-30)), 0.0f, 0.0f, 0.0f};
  for (std::size_t c = 0; c < 3; ++c) {
    const auto e = static_cast<float>(scale * st.environment_irradiance[c]);
    (&u.sky_ambient.x)[c] = e;
  }
}

}  // namespace ocean::render
