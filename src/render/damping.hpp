// The damping of the bands (src/render, private; docs/rendering.md R.24, R.63): an RGBA16F 2-D
// array of three layers (the weights of cascades 0–3 and 4–7; the depth and the fraction of
// breaking waves), filled from a DampingGrid through a staging buffer by Renderer::set_damping;
// 1×1 until then, so the scene set's binding is always valid. The shaders read it in
// shaders/damping.glsl.
#pragma once

#include <array>

#include "ocean/vk.hpp"
#include "pass.hpp"

namespace ocean::render {

// render pass 400: DampingPass — the damping of the bands (R.24)
struct DampingPass : Pass {
  vk::Image image;
  vk::Buffer staging;
  VkSampler sampler = VK_NULL_HANDLE;
  bool pending = false;    // staging holds weights not yet copied into `image`
  std::uint32_t side = 0;  // N of `image`
  shader::DampingUniforms uniforms{};
  std::array<double, 2> origin_m{};  // world (x0, z0); the uniforms hold it relative to O

  Status create(Renderer::State& st);
  void destroy(Renderer::State& st);
  void scene_images(const Renderer::State& st, SceneImages& images) const;
  void fill_uniforms(const Renderer::State& st, const View& view, shader::FrameUniforms& u) const;
  void upload(Renderer::State& st, VkCommandBuffer cmd);
};

}  // namespace ocean::render
