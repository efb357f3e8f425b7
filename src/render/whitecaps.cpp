// The sea's whitecaps as patches (whitecaps.hpp; docs/rendering.md R.11b): each sine's vector,
// amplitude and phase at the camera x_eye and time t, k·x_eye − ω·t + ψ wrapped in double
// precision, so the shader's k·(x − x_eye) stays small however far the camera is from the
// world's origin (R.16), as the ripples' (R.62).
#include "whitecaps.hpp"

#include <cmath>
#include <numbers>

#include "far_map.hpp"
#include "state.hpp"

namespace ocean::render {

void WhitecapPass::fill_uniforms(const Renderer::State& st, const View& view,
                                 shader::FrameUniforms& u) const {
  u.whitecaps.count = 0.0f;
  // Not on a sphere (no foam drawn there) and not when the view leaves them out.
  if (!enabled || view.sphere.enabled || !view.shading.whitecap_patches) return;
  const double t = pass<FarFieldPass>(st).time_s;  // the frame's time (R.13b)
  const double ex = view.camera.position_m.x, ez = view.camera.position_m.z;
  constexpr double kTwoPi = 2.0 * std::numbers::pi;
  for (std::size_t i = 0; i < waves.size(); ++i) {
    const WhitecapWave& w = waves[i];
    double phase =
        std::fmod(w.kx_radpm * ex + w.kz_radpm * ez - w.omega_radps * t + w.phase_rad, kTwoPi);
    if (phase < 0.0) phase += kTwoPi;
    u.whitecaps.waves[i] = {static_cast<float>(w.kx_radpm), static_cast<float>(w.kz_radpm),
                            static_cast<float>(w.amplitude), static_cast<float>(phase)};
  }
  u.whitecaps.count = static_cast<float>(waves.size());
}

}  // namespace ocean::render
