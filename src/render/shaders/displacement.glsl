// displacement.glsl — the sum of the cascades' displacement maps at an undisplaced position
// (Aebi, VR Ocean, eq. 44; sampling M.7.6), read from one displacement array: the frame's, or for
// motion vectors the previous frame's (R.26). Each cascade fades out where the mesh is too coarse
// to carry its dominant wavelength (R.9); beyond the far field's D_min the cascades are read
// through hex tiles and cascade 0 blends into the far field's noise (R.13, R.14); the damping
// scales each band (R.24). The border fade (R.10) is the caller's.
#ifndef OCEAN_RENDER_DISPLACEMENT_GLSL
#define OCEAN_RENDER_DISPLACEMENT_GLSL

#include "damping.glsl"
#include "far_field.glsl"
#include "planet.glsl"

float geometry_weight(int c, float spacing_m) {
  // Full while the vertex spacing is below a quarter of the cascade's dominant wavelength, none
  // at half of it (the mesh's Nyquist limit) (R.9).
  return clamp(2.0 - 4.0 * spacing_m / u.cascades[c].wavelength_m, 0.0, 1.0);
}

// (Dx, h, Dz) of the cascades at xz (relative to the origin, R.16) for a mesh of this spacing.
vec3 sea_displacement(sampler2DArray map, vec2 xz, float spacing) {
  vec3 displacement = vec3(0.0);
  int cascades = int(u.cascade_count);
  DampingSample damping = damping_at(xz);  // mask and bathymetry (R.24)
  float ratio = far_ratio_at(xz);
  vec2 blend = preserving_weights(ratio);  // (simulation, far field)
  for (int c = 0; c < cascades; ++c) {
    float w = geometry_weight(c, spacing);
    if (w <= 0.0 && c > 0) continue;
    vec2 uv = cascade_uv(xz, c);
    float hex = hex_ratio(ratio, u.cascades[c].patch_size_m, spacing);
    vec2 mixing = preserving_weights(hex);  // (plain, hex-tiled)
    vec3 plain = vec3(0.0), tiled = vec3(0.0);
    if (hex < 1.0) plain = textureLod(map, vec3(uv, float(c)), 0.0).xyz;
    if (hex > 0.0) {
      HexTaps taps = hex_taps(uv, c);
      for (int i = 0; i < 3; ++i)
        tiled += taps.weight[i] * textureLod(map, vec3(uv + taps.offset[i], float(c)), 0.0).xyz;
    }
    vec3 sim = w * band_weight(damping, c) * (mixing.x * plain + mixing.y * tiled);
    if (c == 0 && ratio > 0.0) {  // cascade 0 becomes the noise (R.13)
      // The map where it resolves more than the mesh does, the mean over a vertex spacing
      // (R.13b); the analytic octaves, each faded as R.9, elsewhere.
      float from_map = far_map_weight(xz, spacing);
      float h = 0.0;
      if (from_map > 0.0) {
        float texel = u.far_map.size_m / u.far_map.resolution;
        float lod = clamp(log2(max(spacing / texel, 1.0)), 0.0, u.far_map.coarsest_mip);
        h = from_map * textureLod(far_map, vec3(far_map_uv(xz), 0.0), lod).x;
      }
      vec3 share = 1.0 - from_map * u.far_map.in_map.xyz;  // octaves not from the map
      if (max(share.x, max(share.y, share.z)) > 0.0) {
        float ha, sx, sz;
        vec3 cell = u.far_field.cell_m.xyz;
        far_noise_at(xz, share * clamp(2.0 - 4.0 * spacing / cell, 0.0, 1.0), ha, sx, sz);
        h += ha;
      }
      sim = blend.x * sim + vec3(0.0, blend.y * h, 0.0);
    }
    displacement += sim;
  }
  return displacement;
}

#endif
