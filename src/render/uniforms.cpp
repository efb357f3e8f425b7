// The per-frame inputs of the shaders that every pass shares: FrameUniforms
// (shaders/render_shared.h) from the view, the shading and the configured cascades; each pass
// adds its own part (pass.hpp's fill_uniforms).
#include <cmath>

#include "state.hpp"

namespace ocean::render {

namespace {

shader::vec3 to_vec3(const std::array<double, 3>& v) {
  return {static_cast<float>(v[0]), static_cast<float>(v[1]), static_cast<float>(v[2])};
}

}  // namespace

void fill_uniforms(const Renderer::State& st, const View& view, const lod::Mat4& vp,
                   shader::FrameUniforms& u) {
  const lod::LodSelection& sel = st.selection;
  for (int i = 0; i < 16; ++i)
    u.view_proj.m[i] = static_cast<float>(vp.m[static_cast<std::size_t>(i)]);
  const lod::Vec3 eye = view.camera.position_m;  // relative to the grid centre (R.16)
  u.camera_pos_m = to_vec3({eye.x - sel.grid_centre_x_m, eye.y, eye.z - sel.grid_centre_z_m});
  u.fov_y_rad = static_cast<float>(lod::vertical_fov_rad(view.camera));
  const ShadingParams& sh = view.shading;
  u.sun_dir = to_vec3(sun_direction(sh.sun_azimuth_deg, sh.sun_elevation_deg));
  u.footprint_scale = 1.0f;  // the whole pixel; temporal anti-aliasing narrows it (R.61)
  u.water_colour = to_vec3(sh.water_colour);
  u.crest_scatter = static_cast<float>(sh.crest_scatter);
  u.foam_brightness = static_cast<float>(sh.foam_brightness);
  // The waves shorter than the finest cascade: their slope variance where the sea names its wind,
  // the shading's roughness parameter otherwise (R.5).
  u.roughness = static_cast<float>(st.unresolved_slope_variance
                                       ? std::sqrt(*st.unresolved_slope_variance)
                                       : sh.roughness);
  u.map_base_normal_length = static_cast<float>(st.map_base_normal_length);
  u.fog_density_per_m = static_cast<float>(sh.fog_density_per_m);
  const Sky::Air air = Sky(sh).air();
  u.air_rayleigh = {static_cast<float>(air.rayleigh_per_m[0]),
                    static_cast<float>(air.rayleigh_per_m[1]),
                    static_cast<float>(air.rayleigh_per_m[2]),
                    sh.aerial_perspective ? static_cast<float>(air.rayleigh_height_m) : 0.0f};
  u.air_mie = {static_cast<float>(air.mie_per_m), static_cast<float>(air.mie_height_m),
               static_cast<float>(sh.aerosol_g), static_cast<float>(sh.sky_brightness)};
  u.grid_centre_m = {0.0f, 0.0f};  // the origin of the positions the GPU sees (R.16)
  u.ocean_size_m = static_cast<float>(view.ocean_size_m);
  u.border_fade_m = static_cast<float>(0.1 * view.ocean_size_m);  // R.10
  u.lod_scale = static_cast<float>(view.quality.lod_scale);
  u.vertices = static_cast<float>(view.quality.vertices);
  u.debug_view =
      static_cast<float>(view.debug == DebugView::lod_colours ? OCEAN_RENDER_DEBUG_LOD_COLOURS
                         : view.debug == DebugView::normals   ? OCEAN_RENDER_DEBUG_NORMALS
                                                              : OCEAN_RENDER_DEBUG_SHADED);
  u.cascade_count = static_cast<float>(st.displacement_view != VK_NULL_HANDLE ? st.cascades : 0);
  u.hs_m = static_cast<float>(st.hs_m);
  for (int c = 0; c < kMaxCascades; ++c)
    u.cascades[c] = st.cascade_params[static_cast<std::size_t>(c)];
  u.foam_weighted = st.foam_weights.empty() ? 0.0f : 1.0f;
  for (std::size_t c = 0; c < st.foam_weights.size() && c < kMaxCascades; ++c) {
    shader::vec4& w = u.foam_weights[c / 4];
    (c % 4 == 0   ? w.x
     : c % 4 == 1 ? w.y
     : c % 4 == 2 ? w.z
                  : w.w) = static_cast<float>(st.foam_weights[c]);
  }
  u.foam_streak = {static_cast<float>(st.foam_drift_mps[0] * st.foam_decay_time_s),
                   static_cast<float>(st.foam_drift_mps[1] * st.foam_decay_time_s), 0.0f, 0.0f};
}

// Inverse of a 4×4 column-major matrix by cofactors (double precision).
std::array<double, 16> inverse(const std::array<double, 16>& m) {
  std::array<double, 16> inv{};
  inv[0] = m[5] * m[10] * m[15] - m[5] * m[11] * m[14] - m[9] * m[6] * m[15] + m[9] * m[7] * m[14] +
           m[13] * m[6] * m[11] - m[13] * m[7] * m[10];
  inv[4] = -m[4] * m[10] * m[15] + m[4] * m[11] * m[14] + m[8] * m[6] * m[15] -
           m[8] * m[7] * m[14] - m[12] * m[6] * m[11] + m[12] * m[7] * m[10];
  inv[8] = m[4] * m[9] * m[15] - m[4] * m[11] * m[13] - m[8] * m[5] * m[15] + m[8] * m[7] * m[13] +
           m[12] * m[5] * m[11] - m[12] * m[7] * m[9];
  inv[12] = -m[4] * m[9] * m[14] + m[4] * m[10] * m[13] + m[8] * m[5] * m[14] -
            m[8] * m[6] * m[13] - m[12] * m[5] * m[10] + m[12] * m[6] * m[9];
  inv[1] = -m[1] * m[10] * m[15] + m[1] * m[11] * m[14] + m[9] * m[2] * m[15] -
           m[9] * m[3] * m[14] - m[13] * m[2] * m[11] + m[13] * m[3] * m[10];
  inv[5] = m[0] * m[10] * m[15] - m[0] * m[11] * m[14] - m[8] * m[2] * m[15] + m[8] * m[3] * m[14] +
           m[12] * m[2] * m[11] - m[12] * m[3] * m[10];
  inv[9] = -m[0] * m[9] * m[15] + m[0] * m[11] * m[13] + m[8] * m[1] * m[15] - m[8] * m[3] * m[13] -
           m[12] * m[1] * m[11] + m[12] * m[3] * m[9];
  inv[13] = m[0] * m[9] * m[14] - m[0] * m[10] * m[13] - m[8] * m[1] * m[14] + m[8] * m[2] * m[13] +
            m[12] * m[1] * m[10] - m[12] * m[2] * m[9];
  inv[2] = m[1] * m[6] * m[15] - m[1] * m[7] * m[14] - m[5] * m[2] * m[15] + m[5] * m[3] * m[14] +
           m[13] * m[2] * m[7] - m[13] * m[3] * m[6];
  inv[6] = -m[0] * m[6] * m[15] + m[0] * m[7] * m[14] + m[4] * m[2] * m[15] - m[4] * m[3] * m[14] -
           m[12] * m[2] * m[7] + m[12] * m[3] * m[6];
  inv[10] = m[0] * m[5] * m[15] - m[0] * m[7] * m[13] - m[4] * m[1] * m[15] + m[4] * m[3] * m[13] +
            m[12] * m[1] * m[7] - m[12] * m[3] * m[5];
  inv[14] = -m[0] * m[5] * m[14] + m[0] * m[6] * m[13] + m[4] * m[1] * m[14] - m[4] * m[2] * m[13] -
            m[12] * m[1] * m[6] + m[12] * m[2] * m[5];
  inv[3] = -m[1] * m[6] * m[11] + m[1] * m[7] * m[10] + m[5] * m[2] * m[11] - m[5] * m[3] * m[10] -
           m[9] * m[2] * m[7] + m[9] * m[3] * m[6];
  inv[7] = m[0] * m[6] * m[11] - m[0] * m[7] * m[10] - m[4] * m[2] * m[11] + m[4] * m[3] * m[10] +
           m[8] * m[2] * m[7] - m[8] * m[3] * m[6];
  inv[11] = -m[0] * m[5] * m[11] + m[0] * m[7] * m[9] + m[4] * m[1] * m[11] - m[4] * m[3] * m[9] -
            m[8] * m[1] * m[7] + m[8] * m[3] * m[5];
  inv[15] = m[0] * m[5] * m[10] - m[0] * m[6] * m[9] - m[4] * m[1] * m[10] + m[4] * m[2] * m[9] +
            m[8] * m[1] * m[6] - m[8] * m[2] * m[5];
  const double det = m[0] * inv[0] + m[1] * inv[4] + m[2] * inv[8] + m[3] * inv[12];
  for (double& v : inv) v /= det;
  return inv;
}

}  // namespace ocean::render
