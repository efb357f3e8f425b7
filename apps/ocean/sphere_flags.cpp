// The flags of the sea on a sphere (see sphere_flags.hpp; docs/rendering.md R.30–R.38).
#include "sphere_flags.hpp"

#include <algorithm>
#include <cmath>

#include "options.hpp"

namespace ocean::cli {

namespace {
constexpr NumberOption<double> kLatitude{
    .flag = "--latitude", .accept = Accept::in_range, .lo = -90.0, .hi = 90.0};
constexpr NumberOption<double> kLongitude{
    .flag = "--longitude", .accept = Accept::in_range, .lo = -360.0, .hi = 360.0};
constexpr NumberOption<double> kAltitude{.flag = "--altitude", .accept = Accept::positive};
}  // namespace

void add_sphere_flags(CLI::App& command, SphereFlags& f) {
  command.add_flag("--sphere", f.enabled,
                   "draw the sea on a sphere of radius --planet-radius (a planet seen whole); "
                   "--camera and --target are then metres east, up and north of the surface "
                   "point at --latitude, --longitude");
  add_option(command, kLatitude, f.latitude,
             "with --sphere: latitude of the view's surface point, "
             "degrees (default 0)");
  add_option(command, kLongitude, f.longitude,
             "with --sphere: longitude of the view's surface point, degrees (default 0)");
  add_option(command, kAltitude, f.altitude,
             "with --sphere: the camera's height above that point, m (lifts --camera and "
             "--target together so that the camera's Y is this)");
}

Status parse_sphere_flags(const SphereFlags& f, render::View& view) {
  if (!f.enabled) {
    if (f.latitude != SphereFlags{}.latitude || f.longitude != SphereFlags{}.longitude ||
        !f.altitude.empty())
      return invalid_argument("--latitude, --longitude and --altitude need --sphere");
    return {};
  }
  Result<double> lat = parse(kLatitude, f.latitude);
  if (!lat.ok()) return lat.status();
  Result<double> lon = parse(kLongitude, f.longitude);
  if (!lon.ok()) return lon.status();
  if (!f.altitude.empty()) {
    Result<double> alt = parse(kAltitude, f.altitude);
    if (!alt.ok()) return alt.status();
    const double lift = alt.value() - view.camera.position_m.y;
    view.camera.position_m.y += lift, view.camera.target_m.y += lift;
  }
  if (std::isinf(view.planet_radius_m))
    return invalid_argument("--sphere needs a finite --planet-radius");
  view.sphere = {.enabled = true, .latitude_deg = lat.value(), .longitude_deg = lon.value()};
  if (Status s = render::validate_sphere(view); !s.ok())
    return invalid_argument("--sphere: " + s.message());
  // Depth range: the far plane past the horizon's distance √((R + h)² − R²) (R.37).
  const double r = view.planet_radius_m;
  const lod::Vec3 c = view.camera.position_m;
  const double h = std::sqrt(c.x * c.x + (c.y + r) * (c.y + r) + c.z * c.z) - r;
  view.camera.near_m = std::max(0.2, 0.005 * h);
  view.camera.far_m =
      std::max(2.0e5, 1.5 * (std::sqrt(h * (2.0 * r + h)) + std::sqrt(2.0 * r * 20.0)));
  return {};
}

}  // namespace ocean::cli
