// The renderer's parameter checks and names (ocean/render.hpp): shading values, debug views,
// views.
#include <cmath>
#include <string>
#include <utility>

#include "ocean/render.hpp"

namespace ocean::render {

Status validate(const ShadingParams& p) {
  const std::pair<std::string_view, std::array<double, 3>> checks[] = {
      {"sun_azimuth_deg", {p.sun_azimuth_deg, -360.0, 360.0}},
      {"sun_elevation_deg", {p.sun_elevation_deg, -89.9, 90.0}},
      {"sun_irradiance", {p.sun_irradiance, 1e-6, 1e6}},
      {"sky_brightness", {p.sky_brightness, 0.0, 1e3}},
      {"aerosol", {p.aerosol, 0.0, 100.0}},
      {"aerosol_g", {p.aerosol_g, 0.0, 0.99}},
      {"water_colour[0]", {p.water_colour[0], 0.0, 1.0}},
      {"water_colour[1]", {p.water_colour[1], 0.0, 1.0}},
      {"water_colour[2]", {p.water_colour[2], 0.0, 1.0}},
      {"crest_scatter", {p.crest_scatter, 0.0, 100.0}},
      {"foam_brightness", {p.foam_brightness, 0.0, 100.0}},
      {"roughness", {p.roughness, 1e-3, 1.0}},
      {"fog_density_per_m", {p.fog_density_per_m, 0.0, 1.0}},
      {"exposure", {p.exposure, 1e-6, 1e6}},
  };
  for (const auto& [name, c] : checks) {
    if (Status s = require_in_range(name, c[0], c[1], c[2]); !s.ok()) return s;
  }
  return {};
}

std::string_view to_string(DebugView view) { return name_of(kDebugViewNames, view, "shaded"); }

Result<DebugView> parse_debug_view(std::string_view name) {
  if (std::optional<DebugView> v = value_of(kDebugViewNames, name)) return *v;
  return invalid_argument("view = " + excerpt(name) + " is not a view: must be " +
                          name_list(kDebugViewNames, ", ", " or "));
}

// The water seen from below (R.50–R.51); here, not in underwater.cpp, so that the view's checks
// link without the renderer's device code.
Status validate(const Underwater& underwater) {
  return require_in_range("underwater scattering_per_m", underwater.scattering_per_m, 0.0, 10.0);
}

Status validate(const View& view) {
  if (Status s = lod::validate(view.camera); !s.ok()) return s;
  if (Status s = lod::validate(view.quality); !s.ok()) return s;
  if (Status s = require_in_range("ocean_size_m", view.ocean_size_m, lod::kMinOceanSize_m,
                                  lod::kMaxOceanSize_m);
      !s.ok())
    return s;
  if (!std::isfinite(view.skirt_half_extent_m))
    return invalid_argument("skirt_half_extent_m must be finite");
  if (view.skirt_half_extent_m > 0.0 && view.skirt_half_extent_m <= 0.5 * view.ocean_size_m)
    return invalid_argument("skirt_half_extent_m = " + std::to_string(view.skirt_half_extent_m) +
                            " must exceed half the ocean size");
  if (!(view.planet_radius_m > 0.0))  // NaN fails too
    return invalid_argument("planet_radius_m = " + format_number(view.planet_radius_m) +
                            " must be > 0 (infinity: a flat world)");
  if (Status s = validate(view.far_field); !s.ok()) return s;
  for (std::size_t i = 0; i < view.objects.size(); ++i)
    for (double m : view.objects[i].model)
      if (!std::isfinite(m))
        return invalid_argument("objects[" + std::to_string(i) + "].model is not finite");
  if (Status s = validate(view.seabed); !s.ok()) return s;
  if (view.sphere.enabled)
    if (Status s = validate_sphere(view); !s.ok()) return s;
  if (Status s = validate(view.underwater); !s.ok()) return s;
  if (Status s = validate(view.tessellation); !s.ok()) return s;
  if (view.temporal_aa.enabled &&
      !(view.temporal_aa.current_weight > 0.0 && view.temporal_aa.current_weight <= 1.0))
    return invalid_argument("temporal_aa.current_weight: must be in (0, 1]");
  return validate(view.shading);
}

}  // namespace ocean::render
