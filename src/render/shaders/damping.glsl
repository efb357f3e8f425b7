// damping.glsl — the damping of the cascades by a mask and a bathymetry (docs/waves.md
// W.12–W.13; docs/rendering.md R.24): per-band amplitude weights and the water depth, baked on
// the CPU (waves::Damping::band_weights) into a square world grid; weight 1 and deep water
// outside it. The vertex shader scales each cascade's displacement, the fragment shader its
// slope, foam and roughness, and tints shallow water by the seabed seen through it.
#ifndef OCEAN_RENDER_DAMPING_GLSL
#define OCEAN_RENDER_DAMPING_GLSL

#include "render_common.glsl"

layout(set = 0, binding = OCEAN_RENDER_BINDING_DAMPING) uniform sampler2DArray damping_map;

struct DampingSample {
  vec4 low;   // weights of cascades 0–3
  vec4 high;  // weights of cascades 4–7
  float depth_m;
  float breaking;  // Q_b, the fraction of breaking waves (W.26): the surf's foam coverage (R.63)
};

DampingSample damping_at(vec2 xz) {
  DampingSample d = DampingSample(vec4(1.0), vec4(1.0), OCEAN_RENDER_DEEP_M, 0.0);
  if (u.damping.resolution <= 0.0) return d;
  vec2 uv = (xz - u.damping.origin_m) / u.damping.size_m;
  if (any(lessThan(uv, vec2(0.0))) || any(greaterThan(uv, vec2(1.0)))) return d;
  d.low = textureLod(damping_map, vec3(uv, 0.0), 0.0);
  d.high = textureLod(damping_map, vec3(uv, 1.0), 0.0);
  vec2 depth_breaking = textureLod(damping_map, vec3(uv, 2.0), 0.0).xy;
  d.depth_m = depth_breaking.x;
  d.breaking = depth_breaking.y;
  return d;
}

// The grid's depth at xz, m, without the weights: OCEAN_RENDER_DEEP_M off the grid; negative on
// land, its height above the mean sea level (R.64).
float grid_depth_at(vec2 xz) {
  if (u.damping.resolution <= 0.0) return OCEAN_RENDER_DEEP_M;
  vec2 uv = (xz - u.damping.origin_m) / u.damping.size_m;
  if (any(lessThan(uv, vec2(0.0))) || any(greaterThan(uv, vec2(1.0)))) return OCEAN_RENDER_DEEP_M;
  return textureLod(damping_map, vec3(uv, 2.0), 0.0).x;
}

// The land's normal at xz from the grid's heights one cell either side (central differences).
vec3 land_normal(vec2 xz) {
  float e = u.damping.size_m / max(u.damping.resolution, 1.0);
  float dx = grid_depth_at(xz + vec2(e, 0.0)) - grid_depth_at(xz - vec2(e, 0.0));
  float dz = grid_depth_at(xz + vec2(0.0, e)) - grid_depth_at(xz - vec2(0.0, e));
  return normalize(vec3(dx, 2.0 * e, dz));  // h = −d: (−∂h/∂x, 1, −∂h/∂z)
}

float band_weight(DampingSample d, int c) { return c < 4 ? d.low[c] : d.high[c - 4]; }

// Light from a seabed of albedo ρ at depth d that leaves the surface: down and up through d of
// water, T = exp(−2·a·d) per channel with pure water's absorption a (R.24). Irradiance E at the
// surface; a Lambertian bottom sends ρ·E/π.
vec3 seabed_radiance(float depth_m, vec3 irradiance) {
  vec3 t = exp(-2.0 * u.damping.absorption_per_m * depth_m);
  return t * u.damping.bottom_albedo * irradiance / PI;
}

#endif
