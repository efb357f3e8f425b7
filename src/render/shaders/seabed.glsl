// seabed.glsl — the seabed seen through the water (docs/rendering.md R.22–R.23): the view ray
// refracted at the surface normal (Snell's law, n = 1.333), followed to the flat bed, the bed lit
// by the sun and the sky attenuated on their way down and seen attenuated along the view path
// (Beer–Lambert per channel, absorption of pure water after Pope & Fry 1997), mixed with the
// water body's own colour as shallow-water reflectance: R = R∞·(1 − T) + R_bed·T (Maritorena,
// Morel & Gentili 1994, eq. 9, with T the two-way transmittance).
#ifndef OCEAN_SEABED_GLSL
#define OCEAN_SEABED_GLSL

#include "seabed_shared.h"
#include "underwater.glsl"

layout(push_constant, std430) uniform SeabedBlock {
  SeabedPush seabed;
};

const float kWaterIor = 1.333;

// A checker of unit squares, box-filtered over the pixel's footprint w (Quilez, "Filtering
// procedurals"): 0 or 1 where w is small, ½ where it spans many squares.
float filtered_checker(vec2 p, vec2 w) {
  w = max(w, vec2(1e-4));
  vec2 i = 2.0 * (abs(fract((p - 0.5 * w) * 0.5) - 0.5) - abs(fract((p + 0.5 * w) * 0.5) - 0.5)) / w;
  return 0.5 - 0.5 * i.x * i.y;
}

vec3 seabed_albedo(vec2 xz, vec2 footprint) {
  float period = seabed.pattern.x;
  vec3 albedo = seabed.albedo_depth.rgb;
  if (seabed.pattern.y == OCEAN_SEABED_CHECKER) {
    float light = filtered_checker(2.0 * xz / period, 2.0 * footprint / period);
    return albedo * mix(0.25, 1.0, light);
  }
  vec2 p = 6.2831853 * xz / period;  // low sand ripples, faded where finer than the pixel
  float fade = clamp(2.0 - 4.0 * max(footprint.x, footprint.y) / period, 0.0, 1.0);
  return albedo * (1.0 + 0.3 * fade * sin(p.x + 0.6 * sin(0.37 * p.y)) * sin(0.41 * p.y + 1.3));
}

// The colour under the surface: `body` (R∞, the deep water's scattered light, R.11) over the bed
// where the refracted view ray reaches it. P0 the surface point, V towards the camera, N the
// surface normal.
vec3 through_water(vec3 body, vec3 P0, vec3 V, vec3 N) {
  vec3 T = refract(-V, N, 1.0 / kWaterIor);
  // Path length in the water to the bed, m (R.22); on a bathymetry the depth where the ray
  // lands, found by one more step from the depth above it (R.52). Dry land: the bed at once.
  float depth = bed_depth_at(P0.xz, seabed.albedo_depth.a);
  float t = max(P0.y + depth, 0.0) / max(-T.y, 1e-4);
  depth = bed_depth_at(P0.xz + t * T.xz, seabed.albedo_depth.a);
  t = max(P0.y + depth, 0.0) / max(-T.y, 1e-4);
  vec3 P = P0 + t * T;
  // The caustics (R.65) are looked up where the ray refracted by the mean surface lands: the
  // waves' own scrambling of the view, at a pixel's scale, would turn their pattern into noise.
  vec3 T_mean = refract(-V, vec3(0.0, 1.0, 0.0), 1.0 / kWaterIor);
  vec2 P_mean = P0.xz + (max(P0.y + depth, 0.0) / max(-T_mean.y, 1e-4)) * T_mean.xz;
  // Derivatives in uniform control flow, before any pixel leaves.
  vec2 footprint = max(abs(dFdx(P.xz)), abs(dFdy(P.xz))) * u.footprint_scale;
  vec2 mean_footprint = max(abs(dFdx(P_mean)), abs(dFdy(P_mean))) * u.footprint_scale;
  if (seabed.absorption_enabled.a < 0.5 || T.y > -1e-4 || depth >= OCEAN_RENDER_DEEP_M)
    return body;
  vec3 a = seabed.absorption_enabled.rgb;
  // Light on the bed (R.23), focused by the waves (R.65), as underwater.glsl computes it.
  vec3 bed = seabed_albedo(P.xz, footprint) *
             bed_irradiance_at(P_mean, depth, max(mean_footprint.x, mean_footprint.y)) / PI;
  vec3 view = exp(-a * t);
  return body * (1.0 - view * exp(-a * depth)) + bed * view;
}

#endif
