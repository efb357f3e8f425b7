// The sky (src/render, private; docs/rendering.md R.1–R.4, R.17): the sky-view table of the
// analytic sky (sky.cpp) and the irradiances it gives, recomputed only when the sky's parameters
// change, and the HDR environment map (environment.cpp) that replaces both where one is set — a
// 1×1 black image while there is none. The shaders read them in shaders/sky.frag and
// render_common.glsl.
#pragma once

#include <array>
#include <optional>

#include "ocean/vk.hpp"
#include "pass.hpp"

namespace ocean::render {

// render pass 100: SkyPass — the sky-view table and the environment map (R.1–R.4, R.17)
struct SkyPass : Pass {
  vk::Image2D lut;  // the sky-view table (RGBA32F, Sky::kLutWidth × kLutHeight)
  vk::Buffer lut_staging;
  bool lut_pending = false;
  std::optional<ShadingParams> lut_params;  // what the table holds; none before the first draw
  std::array<double, 3> sun_ground{}, sky_ambient{};
  VkSampler sampler = VK_NULL_HANDLE;  // u repeats, v clamps: the table and the environment map
  vk::Image2D environment;
  bool has_environment = false;
  std::array<double, 3> environment_irradiance{};  // on a horizontal plane, before the scale

  // The table, its staging buffer and the sampler (the environment: Renderer::set_environment).
  Status create(Renderer::State& st);
  void destroy(Renderer::State& st);
  void scene_images(const Renderer::State& st, SceneImages& images) const;
  // FrameUniforms::sun_ground and sky_ambient, and environment (R.17) with its irradiance.
  void fill_uniforms(const Renderer::State& st, const View& view, shader::FrameUniforms& u) const;
  // The staged table's copy, before the scene.
  void upload(Renderer::State& st, VkCommandBuffer cmd);
  // Recomputes the table and the irradiances when the sky's parameters changed (select_frame).
  void update(const ShadingParams& shading);
};

}  // namespace ocean::render
