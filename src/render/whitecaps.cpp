// The sea's whitecaps as patches (whitecaps.hpp; docs/rendering.md R.11b): each sine's vector,
// amplitude and phase at the quadtree's centre x_c and time t, k·x_c − ω·t + ψ wrapped in double
// precision, so the shader's k·(x − x_c) stays within the drawn square however far the camera is
// from the world's origin (R.16).
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
  // At the quadtree's centre, the origin of the positions the GPU sees (R.16): the same for a
  // stereo pair's head and a mono view from either eye, so the patches' sharp edges fall alike.
  const double ex = st.selection.grid_centre_x_m, ez = st.selection.grid_centre_z_m;
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
