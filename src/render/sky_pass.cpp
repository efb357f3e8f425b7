// The sky's pass (sky_pass.hpp): the sky-view table recomputed when the sky changes and copied
// before the scene, and the frame's sky uniforms; the environment map's upload is environment.cpp.
#include "sky_pass.hpp"

#include <algorithm>

#include "state.hpp"

namespace ocean::render {

namespace {

bool same_sky(const ShadingParams& a, const ShadingParams& b) {
  return a.sun_azimuth_deg == b.sun_azimuth_deg && a.sun_elevation_deg == b.sun_elevation_deg &&
         a.sun_irradiance == b.sun_irradiance && a.sky_brightness == b.sky_brightness &&
         a.aerosol == b.aerosol && a.aerosol_g == b.aerosol_g;
}

shader::vec3 to_vec3(const std::array<double, 3>& v) {
  return {static_cast<float>(v[0]), static_cast<float>(v[1]), static_cast<float>(v[2])};
}

}  // namespace

Status SkyPass::create(Renderer::State& st) {
  Result<vk::Image2D> table =
      vk::create_image_2d(*st.ctx, VK_FORMAT_R32G32B32A32_SFLOAT, Sky::kLutWidth, Sky::kLutHeight,
                          VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT);
  if (!table.ok()) return table.status();
  lut = table.value();
  Result<vk::Buffer> staging =
      vk::create_buffer(*st.ctx, Sky::kLutWidth * Sky::kLutHeight * 4 * sizeof(float),
                        VK_BUFFER_USAGE_TRANSFER_SRC_BIT, vk::MemoryUse::upload);
  if (!staging.ok()) return staging.status();
  lut_staging = staging.value();
  Result<VkSampler> wrap_u = make_sampler(*st.ctx, true, false, true, 1.0f, false);
  if (!wrap_u.ok()) return wrap_u.status();
  sampler = wrap_u.value();
  return {};
}

void SkyPass::destroy(Renderer::State& st) {
  vk::destroy_image(*st.ctx, lut);
  vk::destroy_image(*st.ctx, environment);
  vk::destroy_buffer(*st.ctx, lut_staging);
  if (sampler != VK_NULL_HANDLE) vkDestroySampler(st.ctx->device, sampler, nullptr);
}

void SkyPass::scene_images(const Renderer::State&, SceneImages& images) const {
  images.add(OCEAN_RENDER_BINDING_SKY_LUT, VK_SHADER_STAGE_FRAGMENT_BIT,
             {sampler, lut.view, VK_IMAGE_LAYOUT_GENERAL});
  // The environment map is addressed as the sky table: u repeats, v clamps.
  images.add(OCEAN_RENDER_BINDING_ENVIRONMENT, VK_SHADER_STAGE_FRAGMENT_BIT,
             {sampler, environment.view, VK_IMAGE_LAYOUT_GENERAL});
}

void SkyPass::update(const ShadingParams& shading) {
  if (lut_params && same_sky(*lut_params, shading)) return;
  const Sky sky(shading);
  sky.fill_lut({static_cast<float*>(lut_staging.mapped),
                static_cast<std::size_t>(Sky::kLutWidth * Sky::kLutHeight * 4)});
  sun_ground = sky.sun_irradiance_ground();
  sky_ambient = sky.sky_irradiance_horizontal();
  lut_params = shading;
  lut_pending = true;
}

void SkyPass::upload(Renderer::State&, VkCommandBuffer cmd) {
  if (!lut_pending) return;
  vk::image_barrier(cmd, lut.image, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_GENERAL,
                    VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT, 0, VK_PIPELINE_STAGE_TRANSFER_BIT,
                    VK_ACCESS_TRANSFER_WRITE_BIT);
  const VkBufferImageCopy region{.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1},
                                 .imageExtent = {Sky::kLutWidth, Sky::kLutHeight, 1}};
  vkCmdCopyBufferToImage(cmd, lut_staging.buffer, lut.image, VK_IMAGE_LAYOUT_GENERAL, 1, &region);
  vk::barrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT);
  lut_pending = false;
}

void SkyPass::fill_uniforms(const Renderer::State&, const View& view,
                            shader::FrameUniforms& u) const {
  u.sun_ground = to_vec3(sun_ground);
  u.sky_ambient = to_vec3(sky_ambient);
  if (!has_environment) {
    u.environment = {0.0f, 0.0f, 0.0f, 0.0f};
    return;
  }
  // The map's radiance scaled by sky_brightness (R.17); > 0 marks it in use (a scale of 0 would
  // be the black sky the analytic model gives for sky_brightness = 0 too). Its irradiance lights
  // the water body and the foam in place of the analytic sky's.
  const double scale = view.shading.sky_brightness;
  u.environment = {static_cast<float>(std::max(scale, 1e-30)), 0.0f, 0.0f, 0.0f};
  for (std::size_t c = 0; c < 3; ++c) {
    const auto e = static_cast<float>(scale * environment_irradiance[c]);
    (&u.sky_ambient.x)[c] = e;
  }
}

}  // namespace ocean::render
