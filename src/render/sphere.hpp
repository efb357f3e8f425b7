// The sea on a sphere (src/render, private; docs/rendering.md R.30–R.38): its pipeline (its own
// 32-byte instances on the patch mesh), the per-frame instance buffer and the cube-sphere
// selection; drawn in place of the flat sea's patches when View::sphere is on.
#pragma once

#include "ocean/sphere.hpp"
#include "ocean/vk.hpp"
#include "pass.hpp"

namespace ocean::render {

// render pass 500: SpherePass — the sea on a sphere (R.30–R.38)
struct SpherePass : Pass {
  VkPipeline pipeline = VK_NULL_HANDLE;
  vk::Buffer instances;  // host-visible, kMaxSphereInstances
  sphere::SphereSelection selection;

  // The pipeline and the instance buffer.
  Status create(Renderer::State& st);
  void destroy(Renderer::State& st);
  // The instanced draws of the selection (prepare_sphere made it), by configuration.
  void record(Renderer::State& st, VkCommandBuffer cmd, const FrameContext& frame);
};

}  // namespace ocean::render
