// The tessellated mesh (src/render, private; docs/rendering.md R.40–R.42): its pipelines where
// the device has tessellation shaders (nothing otherwise) and the per-frame list of visible base
// quads (host-visible); drawn in place of the quadtree's patches when View::tessellation asks.
#pragma once

#include "ocean/vk.hpp"
#include "pass.hpp"

namespace ocean::render {

// render pass 600: TessellationPass — the tessellated mesh (R.40–R.42)
struct TessellationPass : Pass {
  VkPipeline filled = VK_NULL_HANDLE, lines = VK_NULL_HANDLE;
  vk::Buffer cells;

  Status create(Renderer::State& st);
  void destroy(Renderer::State& st);
  // The visible base quads and the tessellation stages, then the ocean (or wireframe) pipeline
  // bound again for the skirt; needs Context::tessellation (Renderer::record checks it).
  void record(Renderer::State& st, VkCommandBuffer cmd, const FrameContext& frame);
};

}  // namespace ocean::render
