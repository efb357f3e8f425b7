// The view of a sphere (sphere_view.hpp; docs/rendering.md R.30, R.38) and its validation.
#include "sphere_view.hpp"

#include <cmath>
#include <numbers>

namespace ocean::render {

namespace {
double dot(const lod::Vec3& a, const lod::Vec3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
}  // namespace

lod::Vec3 LocalAxes::apply(lod::Vec3 p) const {
  return {dot(rows[0], p), dot(rows[1], p), dot(rows[2], p)};
}

lod::Vec3 LocalAxes::to_planet(lod::Vec3 l) const {
  return {l.x * rows[0].x + l.y * rows[1].x + l.z * rows[2].x,
          l.x * rows[0].y + l.y * rows[1].y + l.z * rows[2].y,
          l.x * rows[0].z + l.y * rows[1].z + l.z * rows[2].z};
}

LocalAxes local_axes(const SphereView& s) {
  const double lat = s.latitude_deg * std::numbers::pi / 180.0;
  const double lon = s.longitude_deg * std::numbers::pi / 180.0;
  const double cl = std::cos(lat), sl = std::sin(lat), co = std::cos(lon), so = std::sin(lon);
  // t₁ = (−sin φ, 0, cos φ), n, −t₂ with θ = 90° − latitude, φ = longitude.
  return {{{-so, 0.0, co}, {cl * co, sl, cl * so}, {-sl * co, cl, -sl * so}}};
}

lod::Vec3 camera_planet(const View& view, const LocalAxes& axes) {
  const lod::Vec3 p = view.camera.position_m;
  return axes.to_planet({p.x, p.y + view.planet_radius_m, p.z});
}

Status validate_sphere(const View& view) {
  const SphereView& s = view.sphere;
  if (!(s.latitude_deg >= -90.0 && s.latitude_deg <= 90.0))
    return invalid_argument("sphere.latitude_deg = " + format_number(s.latitude_deg) +
                            " must be in [-90, 90]");
  if (!std::isfinite(s.longitude_deg))
    return invalid_argument("sphere.longitude_deg must be finite");
  if (!std::isfinite(view.planet_radius_m) || !(view.planet_radius_m > 0.0))
    return invalid_argument("planet_radius_m = " + format_number(view.planet_radius_m) +
                            " must be a finite radius > 0 on a sphere");
  if (!(s.finest_patch_m > 0.0) || !std::isfinite(s.finest_patch_m))
    return invalid_argument("sphere.finest_patch_m must be finite and > 0");
  if (!view.objects.empty() || view.seabed.enabled)
    return invalid_argument("objects and a seabed are not drawn on a sphere");
  if (view.debug == DebugView::wireframe)
    return invalid_argument("the wireframe view is not drawn on a sphere (lod is)");
  const lod::Vec3 c = camera_planet(view, local_axes(s));
  const double above = std::sqrt(dot(c, c)) - view.planet_radius_m;
  if (!(above > 0.0))
    return invalid_argument("the camera is inside the planet (" + format_number(above) +
                            " m from its surface)");
  return {};
}

}  // namespace ocean::render
