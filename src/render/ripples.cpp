// The waves shorter than the finest cascade near the eye (ripples.hpp; docs/rendering.md R.62):
// each wave's vector, slope amplitude a·k and phase at the camera x_eye and time t, the phase
// k·x_eye − ω·t + φ wrapped in double precision, so the shader's k·(x − x_eye) stays small however
// far the camera is from the world's origin (R.16).
#include "ripples.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "far_map.hpp"
#include "state.hpp"

namespace ocean::render {

void RipplePass::fill_uniforms(const Renderer::State& st, const View& view,
                               shader::FrameUniforms& u) const {
  u.ripples.count = 0.0f;
  // Not on a sphere, whose camera sees the sea from afar (and positions relative to the camera,
  // R.38), and not when the view leaves them out.
  if (view.sphere.enabled || !view.shading.ripples) return;
  const double t = pass<FarFieldPass>(st).time_s;  // the frame's time (R.13b)
  // At the camera (world metres): the shader's k·(x − x_eye) is then small wherever a pixel
  // resolves a wave.
  const double ex = view.camera.position_m.x, ez = view.camera.position_m.z;
  const std::size_t n = std::min<std::size_t>(waves.size(), OCEAN_RENDER_MAX_RIPPLES);
  constexpr double kTwoPi = 2.0 * std::numbers::pi;
  for (std::size_t i = 0; i < n; ++i) {
    const ShortWaveComponent& w = waves[i];
    const double k = std::hypot(w.kx_radpm, w.kz_radpm);
    double phase = std::fmod(w.kx_radpm * ex + w.kz_radpm * ez - w.omega_radps * t + w.phase_rad,
                             kTwoPi);
    if (phase < 0.0) phase += kTwoPi;
    u.ripples.waves[i] = {static_cast<float>(w.kx_radpm), static_cast<float>(w.kz_radpm),
                          static_cast<float>(w.amplitude_m * k), static_cast<float>(phase)};
  }
  u.ripples.count = static_cast<float>(n);
}

}  // namespace ocean::render
