// The local layer (src/render, private; docs/rendering.md R.19): a 2-D RGBA16F array of two layers
// per cell, (Dx, h, Dz, 0) of the layer and (Δs_x, Δs_z, Δf, 0), what the layer changes in the
// surface's slope and foam, filled through a staging buffer by Renderer::set_local_layer or
// set_local_surface; 1×1 of zeros until then, so the scene set's binding is always valid. The
// shaders read it in shaders/local_layer.glsl.
#pragma once

#include <array>

#include "ocean/vk.hpp"
#include "pass.hpp"

namespace ocean::render {

// render pass 300: LocalSurfacePass — the local layer (R.19)
struct LocalSurfacePass : Pass {
  vk::Image image;
  vk::Buffer staging;
  VkSampler sampler = VK_NULL_HANDLE;
  bool pending = false;    // staging holds a layer not yet copied into `image`
  std::uint32_t side = 0;  // N of `image`
  shader::LocalLayerUniforms uniforms{};
  std::array<double, 2> origin_m{};  // world (x0, z0); the uniforms hold it relative to O

  Status create(Renderer::State& st);
  void destroy(Renderer::State& st);
  void scene_images(const Renderer::State& st, SceneImages& images) const;
  void fill_uniforms(const Renderer::State& st, const View& view, shader::FrameUniforms& u) const;
  void upload(Renderer::State& st, VkCommandBuffer cmd);
};

}  // namespace ocean::render
