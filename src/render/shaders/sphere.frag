#version 450
// Shading of the sea on a sphere (docs/rendering.md R.30–R.38): the cascades' slopes, foam and
// roughness read tri-planarly and expressed in the tangent plane of the sphere's normal (R.35),
// then the water's light as ocean.frag computes it (R.5–R.8, R.11) with the local up the
// sphere's normal. The far field, hex tiles, local layer, damping and seabed of the flat sea are
// not drawn on the sphere.
#include "sphere.glsl"

layout(location = 0) in vec3 planet_q;
layout(location = 1) in vec3 world_pos;
layout(location = 2) in vec3 normal_p;
layout(location = 3) in float height_m;
layout(location = 4) flat in uint level;
layout(location = 0) out vec4 colour;

void main() {
  vec3 n = normalize(normal_p);
  vec3 w = triplanar_weights(n);
  vec3 linear = w / (w.x + w.y + w.z);  // foam, a coverage, blends with weights summing to one
  float alpha0_sq = u.roughness * u.roughness;
  vec3 g = vec3(0.0);  // Σ of the projections' surface gradients, planet axes
  float variance = alpha0_sq, no_foam = 1.0;
  int cascades = u.local.calm > 0.5 ? 0 : int(u.cascade_count);  // calm: no cascades
  for (int c = 0; c < cascades; ++c) {
    float foam = 0.0;
    for (int a = 0; a < 3; ++a) {
      vec4 t = texture(normal_map, vec3(sphere_uv(planet_q, a, c), float(c)));  // uniform flow
      vec2 m = t.xy * 2.0 - 1.0;
      vec2 slope = m / sqrt(max(1.0 - dot(m, m), 0.05));
      g += w[a] * (slope.x * kPlaneE1[a] + slope.y * kPlaneE2[a]);
      variance += w[a] * w[a] * removed_slope_variance(t.w);  // as ocean.frag (R.5)
      foam += linear[a] * t.z;
    }
    if (u.foam_weighted > 0.5)  // as ocean.frag (R.11)
      no_foam -= u.foam_weights[c / 4][c % 4] * foam;
    else
      no_foam *= 1.0 - foam / (1.0 + 0.6 * float(c));
  }
  vec3 up = to_local(n);
  vec3 N = normalize(to_local(n + g - dot(g, n) * n));  // R.35
  float alpha_sq = clamp(variance, 2.5e-4, 1.0);
  float foam = 1.0 - no_foam;
  float distance_m = length(world_pos);
  vec3 V = -world_pos / distance_m;  // the camera is the origin
  vec3 L = u.sun_dir;
  float n_dot_v = dot(N, V);
  if (n_dot_v < 1e-3) {
    N = normalize(N + (1e-3 - n_dot_v) * V);
    n_dot_v = 1e-3;
  }
  vec3 R = reflect(-V, N);
  // The sky table is the day sky of the view's point; where the sun has set under the local
  // horizon the sky fades as Sky::radiance's twilight does (R.4).
  vec3 env = sky_radiance(R) * clamp(1.0 + 10.0 * dot(L, up), 0.0, 1.0);
  float fresnel = fresnel_schlick(n_dot_v);
  // Beckmann facets with Smith masking (R.7), as ocean.frag.
  vec3 H = normalize(V + L);
  float n_dot_l = max(dot(N, L), 0.0), n_dot_h = max(dot(N, H), 0.0);
  float G_over = glitter_lobe(n_dot_h, n_dot_v, n_dot_l, alpha_sq);
  vec3 sun = u.sun_ground * (G_over * fresnel_schlick(max(dot(V, H), 0.0)) * n_dot_l) /
             max(fresnel, 1e-4);
  // The water body lit through the surface (R.11); the sun's height is over the local horizon.
  float sun_up = max(dot(L, up), 0.0);
  float sun_in = sun_up * (1.0 - fresnel_schlick(sun_up));
  vec3 body = u.water_colour * (u.sun_ground * sun_in + u.sky_ambient * sun_up) / PI;
  float crest = clamp(height_m / max(0.5 * u.hs_m, 0.05), 0.0, 2.0);
  body += u.crest_scatter * u.water_colour * u.sun_ground * 0.05 * crest * sun_up;
  vec3 c = body * (1.0 - fresnel) + fresnel * (env + sun);
  vec3 foam_colour = 0.85 * u.foam_brightness *
                     (u.sun_ground * max(dot(N, L), 0.0) + u.sky_ambient * sun_up) / PI;
  c = mix(c, foam_colour, clamp(foam, 0.0, 1.0));
  vec3 fogged = mix(c, fog_colour(-V), horizon_fog(distance_m, dot(V, up)));  // R.8, local up
  float air_weight = planet_air_weight();  // from altitude, the planet's air instead (R.8c)
  if (air_weight > 0.0) {
    mat2x3 air = planet_air(-V, distance_m);
    fogged = mix(fogged, c * air[0] + air[1], air_weight);
  }
  c = fogged;
  if (u.debug_view == OCEAN_RENDER_DEBUG_LOD_COLOURS) {
    const vec3 kLevels[4] = vec3[](vec3(0.9, 0.1, 0.1), vec3(0.9, 0.9, 0.1), vec3(0.1, 0.8, 0.8),
                                   vec3(0.55, 0.25, 0.9));
    c = mix(c, kLevels[level % 4u] * (0.4 + 0.6 * max(dot(N, L), 0.0)) * 0.5, 0.6);
  }
  colour = vec4(c, 1.0);
}
