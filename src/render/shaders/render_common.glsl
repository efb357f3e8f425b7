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

// Horizon-weighted fog of Paleologue (2024), read as (1 − exp(−(dρ)²))·(1 − |v_y|)⁴ (R.8), v_y
// measured from the horizon's direction (horizon_fog_seen).
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

// --- the slope variance the maps' mips carry (R.5) ----------------------------------------------

// The length of the averaged normal that a stored smoothness s encodes: Aebi, VR Ocean, eq. 53
// inverted, (1 − t)(1 + 0.15·t) = (1 − s)², |n| = (t + 2)/3 (packing::
// normal_length_from_smoothness, which gives the level-0 texel's, u.map_base_normal_length).
float stored_normal_length(float smoothness) {
  float r = (1.0 - smoothness) * (1.0 - smoothness);
  float t = (sqrt(0.7225 + 0.6 * (1.0 - r)) - 0.85) / 0.3;
  return (clamp(t, 0.0, 1.0) + 2.0) / 3.0;
}

// The slope variance that averaging removed under a texel of smoothness s: unit normals whose
// slopes vary by v about their mean average to a vector 1/√(1 + v) long, to first order in v
// (Toksvig 2005), here over the length a level-0 texel stores (its base roughness, eq. 49):
// v = (|n|₀/|n|)² − 1.
float removed_slope_variance(float smoothness) {
  float base = u.map_base_normal_length;
  float l = stored_normal_length(smoothness);
  return max(base * base / (l * l) - 1.0, 0.0);
}

// --- the sun's glitter (R.7) ----------------------------------------------------------------

// Smith's masking of a Beckmann surface, Walter et al. (2007) eq. 27's rational fit, for a
// direction of cosine c to the normal and mean square slope m2.
float beckmann_masking(float c, float m2) {
  float a = c / sqrt(m2 * max(1.0 - c * c, 1e-8));
  return a >= 1.6 ? 1.0 : (3.535 * a + 2.181 * a * a) / (1.0 + 2.276 * a + 2.577 * a * a);
}

// D·G/(4·n·l·n·v) of the water's facets: Beckmann's distribution (Walter et al. 2007, eq. 25),
// whose facet slopes are Gaussian with mean square m2, as Cox & Munk (1954) measured the sea's
// from its glitter, with Smith's separable masking.
float glitter_lobe(float n_dot_h, float n_dot_v, float n_dot_l, float m2) {
  float c2 = max(n_dot_h * n_dot_h, 1e-8);
  float D = exp(-(1.0 - c2) / (c2 * m2)) / (PI * m2 * c2 * c2);
  float G = beckmann_masking(n_dot_v, m2) * beckmann_masking(n_dot_l, m2);
  return D * G / max(4.0 * n_dot_v * n_dot_l, 1e-6);
}

// --- the air of a planet seen from any height (R.8c) ------------------------------------------

// Kasten & Young's (1989) relative air mass for a zenith cosine μ ∈ [0, 1] (R.3).
float air_mass(float mu) {
  mu = clamp(mu, 0.0, 1.0);
  return 1.0 / (mu + 0.50572 * pow(96.07995 - degrees(acos(mu)), -1.6364));
}

// The mean of an exponential between its values a and b at the ends of a step (exact when the
// density falls exponentially along the step).
float log_mean(float a, float b) {
  return abs(a - b) <= 1e-4 * max(a, b) ? 0.5 * (a + b) : (a - b) / log(a / b);
}

// The planet's centre relative to the eye, in the view's local axes (R.8c).
vec3 planet_centre() {
  return vec3(u.sphere.local_from_planet[0].w, u.sphere.local_from_planet[1].w,
              u.sphere.local_from_planet[2].w);
}

// Whether the ray along the unit `dir` from a point outside a sphere of radius r, whose centre
// lies at c from the point, meets it.
bool ray_meets_sphere(vec3 c, float r, vec3 dir) {
  float b = dot(c, dir);
  return b > 0.0 && b * b - (dot(c, c) - r * r) > 0.0;
}

const float kAirTopM = 80e3;  // the air's top over the sphere: e^(−10) of the Rayleigh density
const int kAirSteps = 32;

// The eye (the origin of the local axes on a sphere) looking along the unit v for at most t_end
// m: the spherical exponential atmosphere of R.1 between, marched in kAirSteps steps from the
// ray's entry into the air to its exit, its end, or the planet (Nishita et al. 1993): the
// transmittance along the ray and the sun light scattered towards the eye (the sun seen from each
// step through its column above it along the Kasten–Young air mass of its own zenith angle, none
// in the planet's shadow; R.2's phases and R.4's multiple-scattering share). x: transmittance,
// y: in-scattered radiance.
mat2x3 planet_air(vec3 v, float t_end) {
  vec3 centre = planet_centre();
  float radius = u.sphere.radius_m;
  float b = dot(-centre, v), c_top = dot(centre, centre) - (radius + kAirTopM) * (radius + kAirTopM);
  float disc = b * b - c_top;
  if (disc <= 0.0) return mat2x3(vec3(1.0), vec3(0.0));
  float t0 = max(-b - sqrt(disc), 0.0), t1 = min(-b + sqrt(disc), t_end);
  float c_ground = dot(centre, centre) - radius * radius, disc_ground = b * b - c_ground;
  if (disc_ground > 0.0 && -b - sqrt(disc_ground) > 0.0) t1 = min(t1, -b - sqrt(disc_ground));
  if (!(t1 > t0)) return mat2x3(vec3(1.0), vec3(0.0));
  float mu = dot(v, u.sun_dir), g = u.air_mie.z, d = 1.0 + g * g - 2.0 * g * mu;
  float phase_m = (1.0 - g * g) / (4.0 * PI * d * sqrt(d));
  float phase_r = 3.0 / (16.0 * PI) * (1.0 + mu * mu) + 0.25 / (4.0 * PI);
  float h_r = max(u.air_rayleigh.w, 1.0), h_m = u.air_mie.y;
  float dt = (t1 - t0) / float(kAirSteps);
  vec3 tau = vec3(0.0), light = vec3(0.0);
  float z_prev = length(t0 * v - centre) - radius;
  for (int i = 0; i < kAirSteps; ++i) {
    vec3 p = (t0 + (float(i) + 0.5) * dt) * v - centre;
    float r = length(p);
    float z_end = length((t0 + float(i + 1) * dt) * v - centre) - radius;
    float rho_r = log_mean(exp(-z_prev / h_r), exp(-z_end / h_r));
    float rho_m = log_mean(exp(-z_prev / h_m), exp(-z_end / h_m));
    z_prev = z_end;
    vec3 step_tau = (u.air_rayleigh.rgb * rho_r + u.air_mie.x * rho_m) * dt;
    vec3 seen = exp(-(tau + 0.5 * step_tau));
    float z = r - radius, mu_s = dot(p, u.sun_dir) / r;
    float shadow = ray_meets_sphere(-p, radius, u.sun_dir) ? 0.0 : 1.0;
    vec3 column = u.air_rayleigh.rgb * h_r * exp(-z / h_r) + u.air_mie.x * h_m * exp(-z / h_m);
    vec3 sun = shadow * exp(-column * air_mass(mu_s));
    light += seen * sun * (u.air_rayleigh.rgb * rho_r * phase_r + u.air_mie.x * rho_m * phase_m) * dt;
    tau += step_tau;
  }
  return mat2x3(exp(-tau), u.air_mie.w * u.sphere.sun_top * light);
}

// How much of the planet's air (R.8c) replaces the sea-level sky table and the horizon fog: none
// up to 2 km, all from 20 km (the table is the sky seen from sea level).
float planet_air_weight() {
  return u.sphere.enabled > 0.5 && u.air_rayleigh.w > 0.0
             ? smoothstep(2e3, 2e4, u.sphere.camera_altitude_m)
             : 0.0;
}

// The colour distant water and the sky fade to: the sky just above the horizon, this azimuth.
vec3 fog_colour(vec3 view_dir) {
  vec2 h = view_dir.xz;
  float len = length(h);
  return sky_radiance(len > 1e-5 ? vec3(h.x / len, 0.0, h.y / len) : vec3(1.0, 0.0, 0.0));
}

// The sine of the horizon's dip below the horizontal for the eye at its height above the mean sea
// level on the curved world of R.15: the line of sight tangent to y = −d²/(2R) at d = √(2Rh) falls
// by √(2h/R). 0 on a flat world or under the sea.
float horizon_dip_sin() {
  return sqrt(max(4.0 * eye_position().y * u.planet.inv_two_radius_per_m, 0.0));
}

// The direction whose sky (R.1–R.4, a table for an eye at the sea) the eye at its height sees along
// v (R.8d): elevations e lifted to e' = (e + δ)/(1 + δ/(π/2)), δ the horizon's dip, so that the
// sky's horizon — its longest path through the air — lies on the dipped horizon, where the
// line of sight grazes the sea, and the rays between the horizontal and it show the sky's
// gradient run on instead of one colour; the zenith stays. v itself on a flat world.
vec3 sky_direction_seen(vec3 v) {
  float s = horizon_dip_sin();
  if (s <= 0.0) return v;
  float dip = asin(min(s, 1.0));
  float e = asin(clamp(v.y, -1.0, 1.0));
  float lifted = max((e + dip) / (1.0 + dip / (0.5 * PI)), 0.0);
  float len = length(v.xz);
  vec2 across = len > 1e-6 ? v.xz / len : vec2(1.0, 0.0);
  return vec3(across.x * cos(lifted), sin(lifted), across.y * cos(lifted));
}

// The horizon fog (R.8) of a point at height point_y seen distance_m away along −V: the fog's
// distance counted in the haze's air, d·ρ̄ with ρ̄ the mean of e^(−y/H_M) along the path (R.8b's
// mean density, the haze's scale height; heights below the mean sea level taken as 0), so the
// fog of a path near the sea is R.8's and one seen from altitude thins with the air it crosses;
// the view's elevation from the horizon's direction, so that the sea's fog is whole exactly at
// the dipped horizon, where the sky pass shows the same colour (fog_colour).
float horizon_fog_seen(float distance_m, float point_y, vec3 V) {
  float eye_y = max(eye_position().y, 0.0), y = max(point_y, 0.0);
  float density = u.air_mie.y > 0.0 ? mean_air_density(min(eye_y, y), max(eye_y, y), u.air_mie.y)
                                    : 1.0;
  return horizon_fog(distance_m * density, V.y - horizon_dip_sin());
}

#endif
