// The far field (src/render, private; docs/rendering.md R.13, R.13b): the noise fitted to cascade
// 0 by Renderer::configure (R.13), its uniforms (the octaves' lattice at the frame's origin, the
// blend range), and the per-frame noise map as the renderer samples it (R.13b): an RGBA16F image
// with its mip chain, (h, ∂h/∂x, ∂h/∂z, (∂h/∂x)² + (∂h/∂z)²) of the octaves whose cells span at
// least four texels, filled on the device from a float3 buffer — the renderer's own (upload path)
// or a Vulkan backend's (no copy) — by shaders/far_map.comp, the coarser levels by blits. 1×1 while
// there is no map.
#pragma once

#include <array>

#include "ocean/far_noise.hpp"
#include "ocean/vk.hpp"
#include "pass.hpp"

namespace ocean::render {

// render pass 200: FarFieldPass — the far field and its noise map (R.13, R.13b)
struct FarFieldPass : Pass {
  FarFieldNoise noise;              // fitted to cascade 0 by configure() (R.13)
  vk::Image image;                  // the map and its mips (GENERAL once recorded)
  vk::Buffer source;                // host-visible float3 map of the upload path
  VkBuffer bound = VK_NULL_HANDLE;  // the buffer the descriptor set reads
  VkSampler sampler = VK_NULL_HANDLE;
  VkDescriptorSetLayout set_layout = VK_NULL_HANDLE;
  VkDescriptorPool pool = VK_NULL_HANDLE;
  VkDescriptorSet set = VK_NULL_HANDLE;
  VkPipelineLayout layout = VK_NULL_HANDLE;
  vk::ComputePipeline pipeline;
  bool pending = false;    // the image is rebuilt at the next record()
  std::uint32_t side = 0;  // N of `image` (1 while empty)
  // The map's window and the time the far field shows (R.13b): world metres, seconds.
  std::array<double, 2> origin_m{};
  double size_m = 0.0;
  int resolution = 0;  // 0: no map, the analytic noise everywhere
  double time_s = 0.0;

  // The sampler, the compute pass and a 1×1 image of zeros.
  Status create(Renderer::State& st);
  void destroy(Renderer::State& st);
  void scene_images(const Renderer::State& st, SceneImages& images) const;
  // FrameUniforms::far_field, far_octaves and far_map; after the shared uniforms (cascade_count).
  void fill_uniforms(const Renderer::State& st, const View& view, shader::FrameUniforms& u) const;
  // The staged map's conversion and mips, before the scene.
  void upload(Renderer::State& st, VkCommandBuffer cmd);
  // A frame's map staged for the next record() (allocates when N changes).
  Status stage(Renderer::State& st, const FarNoiseFrame& map, double map_time_s);
};

}  // namespace ocean::render
