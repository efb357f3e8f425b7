// Large worlds and the planet's curvature (docs/rendering.md R.15, R.16): the frame's origin
// (the quadtree's centre, in double precision), the camera, instances and uniforms relative to
// it, the skirt's reach to the horizon, and the curvature's bound for the culling boxes.
//
// Sources: Cozzi & Ring, "3D Engine Design for Virtual Globes" (2011), ch. 5 (rendering relative
// to a centre chosen on the CPU in double precision); the horizon's distance √(2Rh) (Young,
// "Dip of the horizon").
#include <cmath>

#include "state.hpp"

namespace ocean::render {

namespace {

// x mod period in [0, period), in double.
double wrap(double x, double period) { return x - period * std::floor(x / period); }

}  // namespace

lod::Camera relative_camera(const lod::Camera& camera, const lod::LodSelection& selection) {
  lod::Camera c = camera;
  c.position_m.x -= selection.grid_centre_x_m, c.position_m.z -= selection.grid_centre_z_m;
  c.target_m.x -= selection.grid_centre_x_m, c.target_m.z -= selection.grid_centre_z_m;
  return c;
}

void write_relative_instances(const lod::LodSelection& selection, double ocean_size_m,
                              lod::PatchInstance* out) {
  // The centre of node (x, y) at level l, −S/2 + (x + 1/2)·s_l from the grid centre (L.2): exact
  // in float for every node, however far the grid centre is from the world's origin.
  for (std::size_t i = 0; i < selection.instances.size(); ++i) {
    lod::PatchInstance p = selection.instances[i];
    const double s = p.size_m;
    p.centre_x_m = static_cast<float>(-0.5 * ocean_size_m + (p.grid_x + 0.5) * s);
    p.centre_z_m = static_cast<float>(-0.5 * ocean_size_m + (p.grid_y + 0.5) * s);
    out[i] = p;
  }
}

double skirt_extent_m(const View& view, double hs_m) {
  if (view.skirt_half_extent_m > 0.0) return view.skirt_half_extent_m;
  const double flat = 10.0 * view.ocean_size_m;
  if (std::isinf(view.planet_radius_m)) return flat;
  const double h = std::abs(view.camera.position_m.y) + hs_m;
  const double horizon = 1.25 * std::sqrt(2.0 * view.planet_radius_m * h);  // R.15
  // A power of two, so that the skirt is rebuilt only when the eye's height doubles.
  return std::max(flat, std::exp2(std::ceil(std::log2(horizon))));
}

double curvature_drop_bound_m(const View& view) {
  if (std::isinf(view.planet_radius_m)) return 0.0;
  // The camera lies within a snap step of the square's centre: no point of the square is
  // farther than S from it.
  return view.ocean_size_m * view.ocean_size_m / (2.0 * view.planet_radius_m);
}

void fill_origin_uniforms(const Renderer::State& st, const View& view, shader::FrameUniforms& u) {
  const double ox = st.selection.grid_centre_x_m, oz = st.selection.grid_centre_z_m;
  const double r = view.planet_radius_m;
  u.planet.inv_two_radius_per_m = std::isinf(r) ? 0.0f : static_cast<float>(0.5 / r);
  u.planet.inv_radius_per_m = std::isinf(r) ? 0.0f : static_cast<float>(1.0 / r);
  constexpr double kWrap = OCEAN_RENDER_ORIGIN_WRAP_M;
  for (int c = 0; c < kMaxCascades; ++c) {
    const double size = st.patch_size_m[static_cast<std::size_t>(c)];
    if (c >= st.cascades || !(size > 0.0)) {
      u.cascade_origin[c] = {0.0f, 0.0f, 0.0f, 0.0f};
      continue;
    }
    // O/L_c in periods, wrapped to a whole number of periods near 2^17 m: the maps repeat every
    // period, the hex tiles (R.14) only every M_c periods.
    const double periods = std::max(1.0, std::floor(kWrap / size));
    u.cascade_origin[c] = {static_cast<float>(wrap(ox / size, periods)),
                           static_cast<float>(wrap(oz / size, periods)), 0.0f, 0.0f};
  }
}

}  // namespace ocean::render
