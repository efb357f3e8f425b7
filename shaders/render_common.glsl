// render_common.glsl — what the ocean renderer's shaders share: the per-frame uniform block
// (layout mirrored by FrameUniforms in src/render/renderer.cpp), the analytic sky, and the
// water's optical constants.
//
// Sources (equations in docs/rendering.md, R.n):
//   - Sky: the table src/render/sky.cpp fills (R.1–R.4), sampled as Hillaire (2020) does.
//   - Fresnel: Schlick (1994) with water's F0 = 0.02 (seed 004) (R.6).

#ifndef OCEAN_RENDER_COMMON_GLSL
#define OCEAN_RENDER_COMMON_GLSL

#define OCEAN_MAX_CASCADES 8
#define PI 3.14159265358979

layout(set = 0, binding = 0, std140) uniform FrameUniforms {
  mat4 view_proj;
  vec4 camera_pos;     // xyz world metres, w = vertical field of view, rad
  vec4 sun_dir;        // xyz unit vector towards the sun, w = 0
  vec4 sun_ground;     // rgb sun irradiance at sea level (plane facing the sun)
  vec4 sky_ambient;    // rgb sky irradiance on a horizontal plane
  vec4 water_colour;   // rgb single-scattering albedo of the water body, w = crest scatter gain
  vec4 params;         // x = foam brightness, y = base roughness α0, z = fog density 1/m, w = 0
  vec4 grid;           // xy grid centre (world x, z), z = ocean size S, w = border fade width
  vec4 lod;            // x = τ, y = V, z = debug view (0 shaded, 1 LOD colours, 2 wireframe),
                       // w = cascade count
  vec4 sky;            // x = significant wave height Hs, m; y, z, w = 0
  // Per cascade: x = patch size L, y = resolution N, z = its dominant wavelength λ (m),
  // w = coarsest-mip level (log2 N).
  vec4 cascades[OCEAN_MAX_CASCADES];
} u;

layout(set = 0, binding = 1) uniform sampler2DArray displacement_map;  // RGBA16F (Dx, h, Dz, 0)
layout(set = 0, binding = 2) uniform sampler2DArray normal_map;  // RGBA8 (nx, nz, foam, smooth.)
layout(set = 0, binding = 3) uniform sampler2D sky_lut;  // sky radiance, u azimuth, v √elevation

// --- sky (R.1–R.4): the sky-view table of src/render/sky.cpp ---------------------------------

vec3 sky_radiance(vec3 v) {
  float elevation = asin(clamp(v.y, 0.0, 1.0));
  float azimuth = atan(v.z, v.x);
  vec2 uv = vec2(azimuth / (2.0 * PI), sqrt(elevation / (0.5 * PI)));
  return texture(sky_lut, uv).rgb;
}

// --- water -----------------------------------------------------------------------------------

float fresnel_schlick(float cos_theta) {  // R.6
  float m = 1.0 - clamp(cos_theta, 0.0, 1.0);
  float m2 = m * m;
  return 0.02 + 0.98 * m2 * m2 * m;
}

// Horizon-weighted fog of seed 004, read as (1 − exp(−(dρ)²))·(1 − |v_y|)⁴ (R.8).
float horizon_fog(float distance_m, float view_y) {
  float d = distance_m * u.params.z;
  float w = 1.0 - abs(view_y);
  w *= w;
  return (1.0 - exp(-d * d)) * w * w;
}

// The colour distant water and the sky fade to: the sky just above the horizon, this azimuth.
vec3 fog_colour(vec3 view_dir) {
  vec2 h = view_dir.xz;
  float len = length(h);
  vec3 dir = len > 1e-5 ? vec3(h.x / len, 0.02, h.y / len) : vec3(1.0, 0.02, 0.0);
  return sky_radiance(normalize(dir));
}

#endif
