// The view from below the surface (src/render, private; ocean/underwater.hpp; docs/rendering.md
// R.50–R.52): the water's optics handed to the shaders as FrameUniforms::underwater. The work is
// in shaders/underwater.glsl: the sky pass fills the pixels whose near-plane point lies under the
// surface with the water's own light, the ocean pass shades the surface seen from below, the
// object pass fogs what lies under water with the camera.
#pragma once

#include "pass.hpp"

namespace ocean::render {

// render pass 800: UnderwaterPass — the view from below the surface (R.50–R.52)
struct UnderwaterPass : Pass {
  void fill_uniforms(const Renderer::State& st, const View& view, shader::FrameUniforms& u) const;
};

}  // namespace ocean::render
