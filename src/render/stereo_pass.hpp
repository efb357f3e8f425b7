// Stereo in one pass (src/render, private; docs/rendering.md R.25): the layered targets of one
// eye's size that the multiview pass draws both eyes into, and its pipelines, made on the first
// stereo frame so that mono renderers pay nothing for them.
#pragma once

#include <cstdint>

#include "ocean/vk.hpp"
#include "pass.hpp"

namespace ocean::render {

// render pass 1000: StereoPass — both eyes in one multiview pass (R.25)
struct StereoPass : Pass {
  vk::Image2D hdr, depth;  // 2 layers each: eye 0 (left), eye 1 (right)
  VkPipeline sky = VK_NULL_HANDLE, ocean = VK_NULL_HANDLE, wire = VK_NULL_HANDLE,
             objects = VK_NULL_HANDLE;

  void destroy(Renderer::State& st);          // the targets and the pipelines
  void release_targets(Renderer::State& st);  // the targets
};

}  // namespace ocean::render
