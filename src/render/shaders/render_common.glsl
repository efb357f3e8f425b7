// render_common.glsl — what the ocean renderer's shaders share: the per-frame uniform block and
// the scene's samplers (layouts and bindings in render_shared.h, shared with the C++ renderer),
// the analytic sky, and the water's optical constants.
//
// Sources (equations in docs/rendering.md, R.n):
//   - Sky: the table src/render/sky.cpp fills (R.1–R.4), sampled as Hillaire (2020) does.
//   - Fresnel: Schlick (1994) with water's F0 = 0.02 (Paleologue 2024, "Fresnel Reflection")
//     (R.6).
//   - Horizon fog: Paleologue 2024, "A bit of fog" (R.8).

#ifndef OCEAN_RENDER_COMMON_GLSL
#define OCEAN_RENDER_COMMON_GLSL

#include "render_shared.h"

#define PI 3.14159265358979

layout(set = 0, binding = OCEAN_RENDER_BINDING_FRAME, std140) uniform Frame {
  FrameUniforms u;
};

// The camera of this view: the frame's one camera, or with OCEAN_MULTIVIEW (stereo in one pass,
// R.25) the eye gl_ViewIndex picks.
#ifdef OCEAN_MULTIVIEW
#extension GL_EXT_multiview : require
vec3 eye_position() { return u.eyes[gl_ViewIndex].camera_pos_m.xyz; }
mat4 eye_view_proj() { return u.eyes[gl_ViewIndex].view_proj; }
#else
vec3 eye_position() { return u.camera_pos_m; }
mat4 eye_view_proj() { return u.view_proj; }
#endif

layout(set = 0, binding = OCEAN_RENDER_BINDING_DISPLACEMENT) uniform sampler2DArray displacement_map;
layout(set = 0, binding = OCEAN_RENDER_BINDING_NORMAL) uniform sampler2DArray normal_map;
layout(set = 0, binding = OCEAN_RENDER_BINDING_SKY_LUT) uniform sampler2D sky_lut;
layout(set = 0, binding = OCEAN_RENDER_BINDING_ENVIRONMENT) uniform sampler2D environment_map;

// --- sky (R.1–R.4): the sky-view table of src/render/sky.cpp, or an environment map (R.17) ----

vec3 sky_radiance(vec3 v) {
  if (u.environment.scale > 0.0) {  // the equirectangular map, below the horizon its horizon
    vec2 uv = vec2(atan(v.z, v.x) / (2.0 * PI), 0.5 - asin(clamp(v.y, 0.0, 1.0)) / PI);
    return u.environment.scale * textureLod(environment_map, uv, 0.0).rgb;
  }
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

// Horizon-weighted fog of Paleologue (2024), read as (1 − exp(−(dρ)²))·(1 − |v_y|)⁴ (R.8).
float horizon_fog(float distance_m, float view_y) {
  float d = distance_m * u.fog_density_per_m;
  float w = 1.0 - abs(view_y);
  w *= w;
  return (1.0 - exp(-d * d)) * w * w;
}

// The mean of e^(−y/H) along a straight path from height y_low to y_high (R.8b).
float mean_air_density(float y_low, float y_high, float scale_height_m) {
  float x = (y_high - y_low) / scale_height_m;
  return exp(-y_low / scale_height_m) * (x < 1e-3 ? 1.0 - 0.5 * x : (1.0 - exp(-x)) / x);
}

// Aerial perspective (R.8b): radiance c from a point at height point_y, distance_m from the eye
// along the unit view_dir (eye to point), as the eye sees it through the sky's atmosphere (R.1–R.4)
// along that segment: c·T plus the sun light the segment scatters towards the eye.
vec3 aerial_perspective(vec3 c, float point_y, float distance_m, vec3 view_dir) {
  if (u.air_rayleigh.w <= 0.0) return c;
  float eye_y = eye_position().y;
  float low = min(eye_y, point_y), high = max(eye_y, point_y);
  vec3 tau_r = u.air_rayleigh.rgb * (distance_m * mean_air_density(low, high, u.air_rayleigh.w));
  float tau_m = u.air_mie.x * distance_m * mean_air_density(low, high, u.air_mie.y);
  vec3 tau = tau_r + tau_m;
  vec3 t = exp(-tau);
  float mu = dot(view_dir, u.sun_dir), g = u.air_mie.z, d = 1.0 + g * g - 2.0 * g * mu;
  float hg = (1.0 - g * g) / (4.0 * PI * d * sqrt(d));
  vec3 phase = (tau_r * (3.0 / (16.0 * PI) * (1.0 + mu * mu) + 0.25 / (4.0 * PI)) + tau_m * hg) /
               max(tau, vec3(1e-20));
  return c * t + u.air_mie.w * u.sun_ground * (1.0 - t) * phase;
}

// The colour distant water and the sky fade to: the sky just above the horizon, this azimuth.
vec3 fog_colour(vec3 view_dir) {
  vec2 h = view_dir.xz;
  float len = length(h);
  vec3 dir = len > 1e-5 ? vec3(h.x / len, 0.02, h.y / len) : vec3(1.0, 0.02, 0.0);
  return sky_radiance(normalize(dir));
}

#endif
