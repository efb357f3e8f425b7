// The waves shorter than the finest cascade drawn as detail normals near the eye (src/render,
// private; docs/rendering.md R.62): SurfaceDescription::short_waves, a sum of sines drawn from
// Elfouhaily et al.'s spectrum beyond the cascades' grids (docs/math.md M.9.4), handed to the
// shaders as FrameUniforms::ripples with their phases at the camera and the frame's time, so that
// shaders/ripples.glsl draws each where a pixel resolves it and leaves it in the roughness
// elsewhere.
#pragma once

#include <vector>

#include "ocean/spectrum.hpp"
#include "pass.hpp"

namespace ocean::render {

// render pass 250: RipplePass — the waves shorter than the finest cascade near the eye (R.62)
struct RipplePass : Pass {
  std::vector<ShortWaveComponent> waves;  // from configure(), by increasing k

  void fill_uniforms(const Renderer::State& st, const View& view, shader::FrameUniforms& u) const;
};

}  // namespace ocean::render
