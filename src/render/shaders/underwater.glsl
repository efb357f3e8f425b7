// underwater.glsl — the sea seen from below (docs/rendering.md R.50–R.52): which side of the
// surface a point or a pixel's near-plane point lies on, the underside of the waves (the sky
// refracted inside Snell's window, total internal reflection beyond the critical angle) and the
// fog of the water's own light along a path through it (Beer–Lambert with absorption and
// scattering).
//
// Sources: Snell's law and the critical angle arcsin(1/n), n = 1.333; the unpolarised Fresnel
// equations (Hecht, "Optics", 2002, §4.6) for the window's transmittance; the n² law of radiance
// across an interface (Mobley, "Light and Water", 1994: L/n² is invariant along a ray); Beer–Lambert
// attenuation with the absorption of pure water (Pope & Fry 1997) and the scattering of clear
// ocean water (Morel 1988).
#ifndef OCEAN_RENDER_UNDERWATER_GLSL
#define OCEAN_RENDER_UNDERWATER_GLSL

#include "planet.glsl"
#include "local_layer.glsl"
#include "damping.glsl"

const float kUnderwaterIor = 1.333;

// The displacement ocean.vert gives the mesh vertex at the undisplaced point xz near the camera
// (R.9, R.10, R.19, R.24; the far field and the hex tiles begin beyond D_min and are left out).
// The weights follow the vertex shader's so the waterline meets the drawn surface.
vec3 surface_displacement(vec2 xz) {
  vec3 d = vec3(0.0);
  vec2 rel = xz - u.grid_centre_m;
  float border = max(abs(rel.x), abs(rel.y));
  float border_weight = clamp((0.5 * u.ocean_size_m - border) / u.border_fade_m, 0.0, 1.0);
  if (border_weight > 0.0 && u.local.calm < 0.5) {
    DampingSample damping = damping_at(xz);
    float dist = length(vec3(xz.x, 0.0, xz.y) - u.camera_pos_m);
    float spacing = max(2.0 * dist / (u.lod_scale * u.vertices), 1e-3);
    for (int c = 0; c < int(u.cascade_count); ++c) {
      float w = clamp(2.0 - 4.0 * spacing / u.cascades[c].wavelength_m, 0.0, 1.0);
      if (w <= 0.0) continue;
      vec3 plain = textureLod(displacement_map, vec3(cascade_uv(xz, c), float(c)), 0.0).xyz;
      d += w * band_weight(damping, c) * plain;
    }
    d *= border_weight;
  }
  return d + local_displacement(xz);
}

// The surface's height above the camera's tangent plane at the displaced point xz (R.50): the
// undisplaced point found by fixed-point iteration x₀ ← xz − D(x₀) (the horizontal
// displacement's slope stays below one where the surface does not fold).
float surface_height(vec2 xz) {
  vec2 x0 = xz;
  for (int i = 0; i < 4; ++i) x0 = xz - surface_displacement(x0).xz;
  return surface_displacement(x0).y - curvature_drop(x0);
}

bool under_surface(vec3 p) { return p.y < surface_height(p.xz); }

// How far the drawn mesh may stray from the exact surface, at most, m: an eye farther than this
// from the surface lies on the same side of the mesh.
const float kMeshMargin_m = 1.0;

// The eye's height above the exact surface at its own position, m.
float eye_above_surface() { return u.camera_pos_m.y - surface_height(u.camera_pos_m.xz); }

// Whether the camera's ray along v, one that meets no part of the drawn surface (the sky pass's
// pixels), runs in the water (R.50). Such a ray stays on one side of the surface, so the side
// where it leaves the drawn sea, at the skirt's outer edge E, is the side it started on: under
// the sea there, y_c + E·v_y/|v_xz| < −E²/(2R). Unlike a height query at the near plane, this
// agrees with the drawn mesh wherever the mesh strays from the exact surface, so the waterline
// shows neither a gap to the sky nor a bar of water.
bool ray_stays_in_water(vec3 v) {
  if (u.sphere.enabled > 0.5) return false;  // the sphere's camera is above its sea (R.30–R.38)
  // An eye deeper than the mesh strays sees the sky only through the hairline cracks where the
  // skirt meets the patches.
  float eye = eye_above_surface();
  if (abs(eye) > kMeshMargin_m) return eye < 0.0;
  float across = length(v.xz), E = u.underwater.skirt_extent_m;
  if (across * E < 1e-3 * abs(v.y)) return v.y < 0.0;  // (near) vertical
  float end_y = u.camera_pos_m.y + E * v.y / across;
  return end_y < -E * E * u.planet.inv_two_radius_per_m;
}

// Whether the camera sees this fragment of the water's surface from below. A height field is
// first met from the side the eye is on, so away from the surface the eye's side decides; near
// it the drawn triangle does: the eye lies below its plane (the normal from the screen-space
// derivatives of the position, exact for a flat triangle, turned up). Call in uniform control
// flow.
bool seen_from_below(vec3 p) {
  vec3 n = cross(dFdx(p), dFdy(p));
  n *= n.y < 0.0 ? -1.0 : 1.0;
  float eye = eye_above_surface();
  if (abs(eye) > kMeshMargin_m) return eye < 0.0;
  return dot(u.camera_pos_m - p, n) < 0.0;
}

// The radiance of an endless path through the water seen at a depth z along the unit
// direction v (R.51): looking down, the water body's light of R.11 just below the surface,
// L∞ = ρ·E/π, dimmed as the downwelling light is, by e^{−a·z} (the diffuse attenuation taken
// as the absorption); brighter towards the light above, by kUnderwaterRise^(1 + v_y): the
// light under water comes mostly from above (a chosen shape, threefold from the nadir to the
// horizon and again to the zenith).
const float kUnderwaterRise = 3.0;
vec3 water_path_radiance(float depth_m, vec3 v) {
  float mu_s = max(u.sun_dir.y, 0.0);
  vec3 e = u.sun_ground * mu_s * (1.0 - fresnel_schlick(mu_s)) + u.sky_ambient;
  vec3 nadir = u.water_colour * e / PI * exp(-u.underwater.absorption_per_m * max(depth_m, 0.0));
  return nadir * pow(kUnderwaterRise, 1.0 + clamp(v.y, -1.0, 1.0));
}

// The eye's depth below the mean sea level, m (≥ 0): where the fog's light is taken.
float eye_depth() { return max(-u.camera_pos_m.y, 0.0); }

// Radiance L0 seen r metres away along v (from the seen point towards the camera: −v is the
// view direction) through the water (R.51).
vec3 water_fog(vec3 radiance, float r, vec3 v) {
  vec3 t = exp(-(u.underwater.absorption_per_m + u.underwater.scattering_per_m) * r);
  return radiance * t + water_path_radiance(eye_depth(), -v) * (1.0 - t);
}

// The bed's depth below the mean sea level at xz, m (R.52): the bathymetry's where the damping
// grid (R.24) covers the point, `flat_depth_m` elsewhere.
float bed_depth_at(vec2 xz, float flat_depth_m) {
  if (u.damping.resolution > 0.0) {
    vec2 uv = (xz - u.damping.origin_m) / u.damping.size_m;
    if (all(greaterThanEqual(uv, vec2(0.0))) && all(lessThanEqual(uv, vec2(1.0))))
      return max(textureLod(damping_map, vec3(uv, 2.0), 0.0).x, 0.0);  // land: the bed at once
  }
  return flat_depth_m;
}

// Irradiance on a bed `depth_m` down (R.23): the sun refracted into the water (its path 1/μ_w
// longer than the depth) and the sky, attenuated vertically.
vec3 bed_irradiance(float depth_m) {
  vec3 a = u.underwater.absorption_per_m;
  float mu_s = max(u.sun_dir.y, 0.0);
  float sin_w = sqrt(max(1.0 - mu_s * mu_s, 0.0)) / kUnderwaterIor;
  float mu_w = sqrt(1.0 - sin_w * sin_w);
  return u.sun_ground * mu_s * (1.0 - fresnel_schlick(mu_s)) * exp(-a * depth_m / mu_w) +
         u.sky_ambient * exp(-a * depth_m);
}

// What a ray from `eye` under the sea along v, one that meets no surface, sees (R.51, R.52): the
// seabed where it reaches one (uniform albedo: the sand's ripples are left out), through the
// water's fog, or the water's own light.
vec3 seen_under_water(vec3 eye, vec3 v) {
  vec3 deep = water_path_radiance(eye_depth(), v);
  if (u.underwater.bed_enabled < 0.5 || v.y > -1e-4) return deep;
  float flat_depth = u.underwater.bed_albedo_depth.a;
  float depth = bed_depth_at(eye.xz, flat_depth);
  float t = max(eye.y + depth, 0.0) / -v.y;
  depth = bed_depth_at(eye.xz + t * v.xz, flat_depth);  // once more where it lands
  t = max(eye.y + depth, 0.0) / -v.y;
  if (depth >= OCEAN_RENDER_DEEP_M) return deep;
  vec3 bed = u.underwater.bed_albedo_depth.rgb * bed_irradiance(depth) / PI;
  return water_fog(bed, t, -v);
}

// Water-to-air transmittance of the unpolarised Fresnel equations at the cosine cos_i of the
// angle of incidence in the water (R.50): 1 − (r_s² + r_p²)/2 with n = 1.333, falling to zero at
// the critical angle (its slope there is infinite, an edge sharper than any pixel) and zero
// beyond it (total internal reflection). Mirrors water_to_air_transmittance (ocean/underwater.hpp).
float water_to_air_transmittance(float cos_i) {
  float ci = clamp(cos_i, 0.0, 1.0), n = kUnderwaterIor;
  float sin_t_sq = n * n * (1.0 - ci * ci);
  if (sin_t_sq >= 1.0) return 0.0;
  float ct = sqrt(1.0 - sin_t_sq);
  float r_s = (n * ci - ct) / (n * ci + ct), r_p = (n * ct - ci) / (n * ct + ci);
  return 1.0 - 0.5 * (r_s * r_s + r_p * r_p);
}

// The transmittance box-filtered over a pixel (R.50): the mean over [cos_i − w/2, cos_i + w/2],
// w the pixel's spread of cos_i (its fwidth), by the midpoint rule on kWindowTaps points. The
// transmittance is continuous (zero at the critical angle), so the mean moves smoothly with the
// footprint: no pixel jumps from sky to mirror, and no level is skipped.
const int kWindowTaps = 8;
float window_transmittance(float cos_i, float width) {
  float sum = 0.0;
  for (int k = 0; k < kWindowTaps; ++k)
    sum += water_to_air_transmittance(cos_i + width * ((float(k) + 0.5) / float(kWindowTaps) - 0.5));
  return sum / float(kWindowTaps);
}

// The underside of the surface at P seen from the camera below (R.50): N the surface's upward
// normal, V towards the camera, cos_width the pixel's spread of dot(V, N) (fwidth, taken in
// uniform control flow). The ray from the water refracts into the air when it meets the surface
// within the critical angle (Snell's window), carrying the sky's radiance times n²·T; the rest,
// 1 − T, is reflected, and beyond the critical angle total internal reflection returns the
// water's own light alone.
vec3 underside_radiance(vec3 P, vec3 N, vec3 V, float cos_width, float foam) {
  vec3 n_water = -N;  // the normal on the camera's side
  float cos_i = dot(V, n_water);
  if (cos_i < 1e-3) n_water = normalize(n_water + (1e-3 - cos_i) * V);  // bent back, as above
  cos_i = max(cos_i, 1e-3);
  // Total internal reflection: the water below, or the seabed, mirrored.
  vec3 depth_light = seen_under_water(P, reflect(-V, n_water));
  float T = window_transmittance(cos_i, cos_width);
  // The refracted ray (Snell's law), held at grazing beyond the critical angle, where the filtered
  // transmittance of a pixel across the edge still looks through it.
  float n = kUnderwaterIor;
  float cos_t = sqrt(max(1.0 - n * n * (1.0 - cos_i * cos_i), 0.0));
  vec3 refracted = normalize(-n * V + (n * cos_i - cos_t) * n_water);
  vec3 c = T * n * n * sky_radiance(refracted) + (1.0 - T) * depth_light;
  // Foam seen from below: a bright diffuse layer lit from above through itself.
  vec3 foam_light =
      0.5 * u.foam_brightness * water_path_radiance(0.0, vec3(0.0, -1.0, 0.0)) /
      max(u.water_colour, vec3(1e-3));
  return mix(c, min(foam_light, vec3(1e3)), clamp(foam, 0.0, 1.0) * 0.5);
}

#endif
