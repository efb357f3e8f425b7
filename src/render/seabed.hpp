// The seabed (src/render, private; docs/rendering.md R.22–R.23): View::seabed pushed for the
// ocean pipeline as shaders/seabed_shared.h's SeabedPush, over the sky pass's push range. The
// shading is shaders/seabed.glsl.
#pragma once

#include "pass.hpp"

namespace ocean::render {

// render pass 700: SeabedPass — the seabed's push constants (R.22–R.23)
struct SeabedPass : Pass {
  // Pushes frame.view.seabed; the ocean pipeline must be bound.
  void record(Renderer::State& st, VkCommandBuffer cmd, const FrameContext& frame);
};

}  // namespace ocean::render
