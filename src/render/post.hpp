// The post pass (src/render, private; docs/rendering.md R.1): the tone map of the linear HDR image
// into the sRGB target — its descriptor set (the HDR image), pipeline layout and pipeline, a
// fullscreen triangle of shaders/sky.vert and shaders/tonemap.frag. Motion vectors, the other
// output after the HDR pass, are motion_pass.hpp.
#pragma once

#include "pass.hpp"
#include "pipeline_desc.hpp"

namespace ocean::render {

// render pass 1300: PostPass — the tone map into the sRGB target
struct PostPass : Pass {
  FullscreenObjects objects;  // its set layout, pool, pipeline layout and pipeline
  VkDescriptorSet set = VK_NULL_HANDLE;

  Status create(Renderer::State& st);
  void destroy(Renderer::State& st);
  // Points the set at the new HDR image.
  Status resize(Renderer::State& st);
  // Tone maps st.hdr (SHADER_READ_ONLY_OPTIMAL) with frame.view.shading.exposure into st.srgb and
  // leaves that in TRANSFER_SRC_OPTIMAL.
  void record(Renderer::State& st, VkCommandBuffer cmd, const FrameContext& frame);
};

}  // namespace ocean::render
