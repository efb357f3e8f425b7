#version 450
// Water shading (docs/rendering.md R.5–R.8, R.11): per-pixel normals, foam and roughness from the
// cascades' mipped maps, sky reflection with Schlick's Fresnel (F0 = 0.02, Paleologue 2024), the
// sun's specular from a Beckmann facet lobe whose roughness the mips encode (Aebi, VR Ocean,
// eqs. 49, 53), light scattered out of the water body and through thin crests, foam, and
// Mitchell's (2005, §4, eq. 5) composition fog(s·(1 − r) + r·(env + sun)) with Paleologue's
// (2024) horizon fog. Beyond the far field's D_min (VR-GIS FFT+Perlin, eq. 6), cascade 0's
// slopes blend into the far field's noise and the cascades are read through hex tiles (R.13,
// R.14).
//
// Sources: Walter et al. (2007) "Microfacet models for refraction through rough surfaces"
// (Beckmann distribution and Smith masking, R.7); Cox & Munk (1954) (Gaussian facet slopes); Toksvig (2005) (normal length as slope variance); Olano
// & Baker (2010) "LEAN mapping" (slope variance adds across layers and filtering, R.5).
#include "far_field.glsl"
#include "planet.glsl"
#include "local_layer.glsl"
#include "damping.glsl"
#include "swash.glsl"
#include "seabed.glsl"
#include "underwater.glsl"
#include "ripples.glsl"
#include "foam_streaks.glsl"
#include "whitecaps.h"

// The objects mirrored in the sea level (R.53): colour, coverage in alpha.
layout(set = 0, binding = OCEAN_RENDER_BINDING_REFLECTION) uniform sampler2D reflection_map;

// The reflection target's texel where the reflected ray R from the water point P shows an
// object: the ray followed for the eye's distance r to P, mirrored in y = 0 and projected. On
// calm water this is P's own pixel, exactly the mirror's geometry; waves move it with R.
vec3 reflection_lookup(vec3 X) {  // (u, v, w of the clip position)
  vec4 clip = u.view_proj * vec4(X.x, -X.y, X.z, 1.0);
  vec2 ndc = clip.xy / max(abs(clip.w), 1e-6);
  return vec3(0.5 + 0.5 * ndc.x, 0.5 - 0.5 * ndc.y, clip.w);
}

// The objects' reflection seen from P, filtered over the pixel's footprint (R.53b): bilinear,
// from the mip level whose texels are as wide as the lookup's spread between neighbouring pixels
// along the footprint's short axis (their reflected rays through the waves the pixels resolve,
// scaled as the rest of the shading's footprint). The long axis would spread an object's image
// sideways across the water where waves turn a quad's rays apart; the short one does not.
vec4 object_reflection(vec3 P, vec3 R, float r) {
  vec3 c = reflection_lookup(P + r * R);
  vec2 gx = dFdx(c.xy) * u.footprint_scale, gy = dFdy(c.xy) * u.footprint_scale;
  if (c.z <= 0.0) return vec4(0.0);
  vec2 size = vec2(textureSize(reflection_map, 0));
  float texels = min(length(gx * size), length(gy * size));
  return textureLod(reflection_map, c.xy, max(log2(max(texels, 1e-6)), 0.0));
}

layout(location = 0) in vec2 world_xz;
layout(location = 1) in vec3 world_pos;
layout(location = 2) flat in uint level;
layout(location = 0) out vec4 colour;

// Wet sand's albedo over dry sand's: light trapped by total internal reflection in the water
// film (Twomey, Bohren & Mergenthaler 1986); a chosen value.
const float kWetSandDarkening = 0.6;

const vec3 kLevelColours[9] = vec3[](vec3(0.9, 0.1, 0.1), vec3(0.95, 0.55, 0.1),
    vec3(0.9, 0.9, 0.1), vec3(0.3, 0.85, 0.2), vec3(0.1, 0.8, 0.8), vec3(0.2, 0.4, 0.95),
    vec3(0.55, 0.25, 0.9), vec3(0.9, 0.3, 0.75), vec3(0.95, 0.95, 0.95));

// One cascade's contribution to a pixel: surface gradient, foam, and the slope variance its mip
// stores above a level-0 texel's: what the filtering averaged away (R.5).
struct Shade {
  vec2 slope;
  float foam;
  float extra;
};
Shade shade_of(vec4 t) {
  vec2 n = t.xy * 2.0 - 1.0;
  float ny = sqrt(max(1.0 - dot(n, n), 0.05));
  return Shade(n / ny, t.z, removed_slope_variance(t.w));
}

void main() {
  int cascades = u.local.calm > 0.5 ? 0 : int(u.cascade_count);  // calm: the layer alone
  float alpha0_sq = u.roughness * u.roughness;
  vec2 slope = vec2(0.0);  // Σ of the cascades' surface gradients, as normal x/y and z/y
  float variance = alpha0_sq;
  float no_foam = 1.0;
  // The mips carry each cascade's mean normal over the pixel and, in the smoothness, the slope
  // variance the averaging removed (Toksvig 2005): every cascade is used at every distance and
  // the filtering alone decides how much of it is detail and how much roughness (R.5).
  vec2 dx = dFdx(world_xz) * u.footprint_scale, dy = dFdy(world_xz) * u.footprint_scale;
  bool below = seen_from_below(world_pos);  // the camera under this surface (R.50)
  float footprint = max(length(dx), length(dy));
  float ratio = far_ratio_at(world_xz);
  vec2 blend = preserving_weights(ratio);  // (simulation, far field)
  DampingSample damping = damping_at(world_xz);  // mask and bathymetry (R.24)
  for (int c = 0; c < cascades; ++c) {
    float inv_size = 1.0 / u.cascades[c].patch_size_m;
    vec2 uv = cascade_uv(world_xz, c);
    float hex = hex_ratio(ratio, u.cascades[c].patch_size_m, footprint);
    vec2 mixing = preserving_weights(hex);  // (plain, hex-tiled)
    Shade plain = Shade(vec2(0.0), 0.0, 0.0), tiled = Shade(vec2(0.0), 0.0, 0.0);
    // Sampled in uniform control flow (implicit derivatives), used where the ratio is below 1.
    // With temporal anti-aliasing the mips of a quarter of the footprint (R.61).
    if (u.footprint_scale == 1.0)
      plain = shade_of(texture(normal_map, vec3(uv, float(c))));
    else
      plain = shade_of(texture(normal_map, vec3(uv, float(c)), log2(u.footprint_scale)));
    // The foam drifted downwind over its age (W.31); the hex tiles, beyond D_min, keep the map's.
    if (u.foam_streak.x != 0.0 || u.foam_streak.y != 0.0)
      plain.foam = streaked_foam(uv, c, dx * inv_size, dy * inv_size, plain.foam);
    float taps_sum = 0.0;
    if (hex > 0.0) {
      HexTaps taps = hex_taps(uv, c);
      taps_sum = taps.weight.x + taps.weight.y + taps.weight.z;
      for (int i = 0; i < 3; ++i) {
        vec4 t = textureGrad(normal_map, vec3(uv + taps.offset[i], float(c)), dx * inv_size,
                             dy * inv_size);
        Shade one = shade_of(t);
        float w = taps.weight[i];
        tiled.slope += w * one.slope;
        tiled.foam += w * one.foam;  // about the mean below, so flecks keep their contrast
        tiled.extra += w * w * one.extra;
      }
    }
    // Foam blends like the slopes, about the cascade's mean coverage (its last mip), with the
    // weights whose squares sum to one: the mean and the contrast of the whitecaps are kept
    // where tiles meet, which a weighted mean would dim (Heitz & Neyret 2018; R.14).
    float mean_foam = textureLod(normal_map, vec3(uv, float(c)), 16.0).z;
    tiled.foam += (1.0 - taps_sum) * mean_foam;
    Shade sh;
    sh.slope = mixing.x * plain.slope + mixing.y * tiled.slope;
    sh.foam = clamp(mean_foam + mixing.x * (plain.foam - mean_foam) +
                        mixing.y * (tiled.foam - mean_foam), 0.0, 1.0);
    sh.extra = mixing.x * mixing.x * plain.extra + mixing.y * mixing.y * tiled.extra;
    if (c == 0 && ratio > 0.0) {  // cascade 0 becomes the noise (R.13)
      // From the map where it resolves more than the pixel does (R.13b): the mean slope over
      // the footprint and, as roughness, the slope variance the averaging removed.
      float from_map = far_map_weight(world_xz, footprint);
      vec2 far_slope = vec2(0.0);
      float unresolved = 0.0;
      if (from_map > 0.0) {
        float inv_size = 1.0 / u.far_map.size_m;
        vec4 m = textureGrad(far_map, vec3(far_map_uv(world_xz), 0.0), dx * inv_size,
                             dy * inv_size);
        far_slope = from_map * m.yz;
        unresolved = from_map * max(m.w - dot(m.yz, m.yz), 0.0);
      }
      // The analytic octaves elsewhere and those the map does not hold: cells below 4 pixels
      // fade (R.13).
      vec3 share = 1.0 - from_map * u.far_map.in_map.xyz;
      if (max(share.x, max(share.y, share.z)) > 0.0) {
        vec3 w = clamp(2.0 - 4.0 * footprint / u.far_field.cell_m.xyz, 0.0, 1.0);
        float h, sx, sz;
        far_noise_at(world_xz, w * share, h, sx, sz);
        far_slope += vec2(sx, sz);
        unresolved += dot(share * (1.0 - w * w), u.far_field.slope_variance.xyz);
      }
      sh.slope = blend.x * sh.slope + blend.y * far_slope;
      sh.extra = blend.x * blend.x * sh.extra + blend.y * blend.y * unresolved;
    }
    float damped = band_weight(damping, c);  // amplitude weight: slopes scale, variances by its square
    sh.slope *= damped;
    sh.foam *= damped;
    sh.extra *= damped * damped;
    slope += sh.slope;
    variance += sh.extra;
    // Breaking (R.11): each cascade's foam is the sea's breaking probability given that
    // cascade, their weighted mean the coverage. Ramp: each cascade's own whitecaps, united, the
    // short cascades' weighted down so they read as streaks and speckle rather than snow.
    if (u.foam_weighted > 0.5)
      no_foam -= u.foam_weights[c / 4][c % 4] * sh.foam;
    else
      no_foam *= 1.0 - sh.foam / (1.0 + 0.6 * float(c));
  }
  // The sea's breaking probability drawn as white patches, its mean kept (R.11b).
  if (u.foam_weighted > 0.5 && u.whitecaps.count > 0.0) {
    float g, v, s2;  // the phases are at the grid's centre, where world_xz is 0 (R.16)
    whitecap_field(u.whitecaps, world_xz.x, world_xz.y, dx.x, dx.y, dy.x, dy.y, g, v, s2);
    no_foam = 1.0 - whitecap_patch(clamp(1.0 - no_foam, 0.0, 1.0), g, v, s2);
  }
  ripples_at(world_xz, dx, dy, slope, variance);  // the short waves the pixel resolves (R.62)
  vec2 local_slope;  // wakes and waveforms (R.19): what they change in slope and foam adds
  float local_foam;
  local_shade(world_xz, local_slope, local_foam);
  slope += local_slope;
  no_foam *= 1.0 - local_foam;
  no_foam *= 1.0 - damping.breaking;  // the surf: the fraction of breaking waves (R.63)
  vec3 N = normalize(vec3(slope.x, 0.0, slope.y) + curved_up(world_xz));  // R.15
  float alpha_sq = clamp(variance, 2.5e-4, 1.0);
  float foam = 1.0 - no_foam;

  vec3 to_camera = eye_position() - world_pos;
  float distance_m = length(to_camera);
  vec3 V = to_camera / distance_m;
  vec3 L = u.sun_dir;
  vec3 N_up = N;
  // Snell's window's filter (R.50), in uniform control flow: the spread of cos θ between the
  // pixels (fwidth) and within the pixel, from the slope variance the filtering removed (a box
  // of width √12·σ holds the spread σ = sin θ·σ_slope).
  float cos_v = dot(V, N_up);
  float cos_width = fwidth(cos_v) * u.footprint_scale + 3.46 * sqrt(max(1.0 - cos_v * cos_v, 0.0)) *
                                        sqrt(max(variance - alpha0_sq, 0.0));
  // Normals that face away from the viewer (grazing views of steep waves) are bent back.
  float n_dot_v = dot(N, V);
  if (n_dot_v < 1e-3) {
    N = normalize(N + (1e-3 - n_dot_v) * V);
    n_dot_v = 1e-3;
  }

  // Reflection of the sky (R.6).
  vec3 R = reflect(-V, N);
  vec3 env = sky_radiance(R);
  vec4 mirrored = object_reflection(world_pos, R, distance_m);  // objects over the sky (R.53)
  env = mirrored.rgb + (1.0 - mirrored.a) * env;
  float fresnel = fresnel_schlick(n_dot_v);

  // Sun specular: Beckmann facets with Cox & Munk's slopes (R.7), radiance reflected = BRDF·E·cos.
  vec3 sun_e = u.sun_ground;
  vec3 H = normalize(V + L);
  float n_dot_l = max(dot(N, L), 0.0);
  float n_dot_h = max(dot(N, H), 0.0);
  float G_over = glitter_lobe(n_dot_h, n_dot_v, n_dot_l, alpha_sq);  // D·G/(4·NdotL·NdotV)
  float fresnel_h = fresnel_schlick(max(dot(V, H), 0.0));
  vec3 sun = sun_e * (G_over * fresnel_h * n_dot_l) / max(fresnel, 1e-4);

  // Light scattered out of the water body (R.11): the water's albedo lit by the sun through the
  // surface and by the sky, plus forward scattering through crests lit from behind.
  vec3 sky_e = u.sky_ambient;
  float sun_in = max(L.y, 0.0) * (1.0 - fresnel_schlick(max(L.y, 0.0)));
  // Over shallow water the column scatters less and the seabed shows through it (R.24); a drawn
  // seabed takes the bathymetry's depth and shows itself instead (R.22, R.52).
  float tint_depth = seabed.absorption_enabled.a > 0.5 ? OCEAN_RENDER_DEEP_M : damping.depth_m;
  vec3 bottom_t = exp(-2.0 * u.damping.absorption_per_m * tint_depth);
  vec3 body = u.water_colour * (sun_e * sun_in + sky_e) / PI * (1.0 - bottom_t) +
              seabed_radiance(tint_depth, sun_e * sun_in + sky_e);
  float height = world_pos.y + curvature_drop(world_xz);  // above the mean level (R.15)
  float crest = clamp(height / max(0.5 * u.hs_m, 0.05), 0.0, 2.0);  // height over Hs/2
  float g = 0.6, mu = dot(-L, V), hg_d = 1.0 + g * g - 2.0 * g * mu;
  float forward = (1.0 - g * g) / (4.0 * PI * hg_d * sqrt(hg_d));  // Henyey–Greenstein
  vec3 through = u.crest_scatter * u.water_colour * sun_e * forward * crest *
                 pow(clamp(0.5 - 0.5 * dot(L, N), 0.0, 1.0), 2.0);
  vec3 s = through_water(body + through, world_pos, V, N);  // a seabed, if any (R.22)

  // Mitchell 2005, eq. 5: s·(1 − r) + r·(env + sun).
  vec3 c = s * (1.0 - fresnel) + fresnel * (env + sun);

  // Foam: a bright diffuse layer over the water (R.11).
  vec3 foam_colour = 0.85 * u.foam_brightness * (sun_e * max(dot(N, L), 0.0) + sky_e) / PI;
  c = mix(c, foam_colour, clamp(foam, 0.0, 1.0));

  if (damping.depth_m < 0.0 && !below) {  // land (R.64): sand under the same sun and sky
    N_up = land_normal(world_xz);
    Swash swash = swash_at(world_xz, -damping.depth_m, footprint);  // the run-up over it (R.67)
    foam = swash.foam;
    // Wet sand, darker: where the swash wets it, else up to half the significant height above
    // the mean level.
    float wet = swash.on ? swash.wet
                         : 1.0 - smoothstep(0.0, max(0.5 * u.hs_m, 0.05), -damping.depth_m);
    vec3 albedo = u.damping.bottom_albedo * mix(1.0, kWetSandDarkening, wet);
    vec3 irradiance = sun_e * max(dot(N_up, L), 0.0) + sky_e * 0.5 * (1.0 + N_up.y);
    c = albedo * irradiance / PI;
    if (swash.film > 0.0) {  // a film of water over the sand: the sheet, or what drains behind it
      float f = fresnel_schlick(max(dot(N_up, V), 1e-3));
      vec3 H_land = normalize(V + L);
      // The film is smooth: the sky's mirror image and the sun's glint on a narrow lobe.
      vec3 glint = sun_e * glitter_lobe(max(dot(N_up, H_land), 0.0), max(dot(N_up, V), 1e-3),
                                        max(dot(N_up, L), 0.0), 0.02) *
                   fresnel_schlick(max(dot(V, H_land), 0.0)) * max(dot(N_up, L), 0.0);
      vec3 film = c * (1.0 - f) * exp(-2.0 * u.damping.absorption_per_m * swash.sheet_m) +
                  f * sky_radiance(reflect(-V, N_up)) + glint;
      c = mix(c, film, swash.film);
      c = mix(c, 0.85 * u.foam_brightness * irradiance / PI, foam);
    }
  }

  if (below) {  // the underside, through the water between it and the camera (R.50, R.51)
    c = seen_through_water(underside_radiance(world_pos, N_up, V, cos_width, foam), distance_m, -V);
  } else {  // the air between (R.8b), then the horizon fog (Paleologue 2024, R.8)
    c = aerial_perspective(c, height, distance_m, -V);
    c = mix(c, fog_colour(-V), horizon_fog_seen(distance_m, height, V));
  }

  if (u.debug_view == OCEAN_RENDER_DEBUG_NORMALS) {  // the shading normal and foam, unfogged
    colour = vec4(0.5 * N_up + 0.5, clamp(foam, 0.0, 1.0));
    return;
  }
  if (u.debug_view == OCEAN_RENDER_DEBUG_LOD_COLOURS) {
    vec3 lc = level < 9u ? kLevelColours[level] : vec3(0.5);
    c = mix(c, lc * (0.4 + 0.6 * max(dot(N, L), 0.0)) * 0.5, 0.6);
  }
  // Alpha: with temporal anti-aliasing, the share of its weight the frame keeps in the blend
  // (R.61): all of it where the pixel resolves the waves, whose glints move over the surface
  // unlike the motion vectors; none where its whole footprint spans the finest cascade's tile,
  // whose mean over every wave the cascade holds changes little from frame to frame.
  float moving = 1.0;
  if (u.footprint_scale < 1.0 && cascades > 0) {
    float finest_m = u.cascades[0].patch_size_m;
    for (int k = 1; k < cascades; ++k) finest_m = min(finest_m, u.cascades[k].patch_size_m);
    moving = 1.0 - smoothstep(0.25 * finest_m, finest_m, footprint / u.footprint_scale);
  }
  colour = vec4(c, moving);
}
