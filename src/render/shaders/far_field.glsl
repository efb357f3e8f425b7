// far_field.glsl — the far field of docs/rendering.md: VR-GIS FFT+Perlin's noise octaves blended
// with cascade 0 (R.13, the noise itself in far_noise.h, shared with the C++ reference) and the
// hex-tiled cascade lookups that keep the periodic cascades from showing their lattice (R.14).
//
// Sources: VR-GIS FFT+Perlin ("CUDA concurrent kernels: FFT + Perlin noise ocean for a VR-GIS
// platform"), eqs. 6–7; Heitz, E. &
// Neyret, F. (2018) "High-performance by-example noise using a histogram-preserving blending
// operator" (the triangle grid, random offsets per vertex, the variance-preserving blend);
// Mikkelsen, M. (2022) "Practical real-time hex-tiling" (sharpened weights, sampling with the
// gradients of the untiled coordinates so the mip does not jump at the tiles' edges).
#ifndef OCEAN_RENDER_FAR_FIELD_GLSL
#define OCEAN_RENDER_FAR_FIELD_GLSL

#include "far_noise.h"
#include "render_common.glsl"

// The Hermite ratio of VR-GIS FFT+Perlin's eq. 6 at an undisplaced sea point; 0 before a
// configuration.
float far_ratio_at(vec2 xz) {
  if (u.far_field.enabled <= 0.0) return 0.0;
  return far_ratio(u.far_field, length(vec3(xz.x, 0.0, xz.y) - eye_position()));
}

// The far field's per-frame noise map (R.13b): (h, ∂h/∂x, ∂h/∂z, (∂h/∂x)² + (∂h/∂z)²) per
// texel with its mip chain, the means over 2^l × 2^l texels (LEAN mapping's first and second
// moments, Olano & Baker 2010).
layout(set = 0, binding = OCEAN_RENDER_BINDING_FAR_MAP) uniform sampler2DArray far_map;

// The three octaves (R.13) at xz relative to the origin, at the frame's time (R.13a).
void far_noise_at(vec2 xz, vec3 weights, out float h, out float sx, out float sz) {
  far_field_noise(u.far_field, u.far_octaves[0], u.far_octaves[1], u.far_octaves[2], xz.x, xz.y,
                  weights.x, weights.y, weights.z, h, sx, sz);
}

// How much of the far field comes from the map at xz for samples `sample_m` apart (R.13b,
// eq. R.13b-1): 1 inside the window, falling to 0 over its outer fade_texels texels (the
// analytic noise beyond, the same field), times the share the map resolves: none where the
// samples are at most a texel apart (the analytic noise, evaluated per sample, is exact there),
// all from two texels on (the map's mips filter what the samples cannot resolve).
float far_map_weight(vec2 xz, float sample_m) {
  if (u.far_map.resolution <= 0.0) return 0.0;
  float texel = u.far_map.size_m / u.far_map.resolution;
  vec2 p = (xz - u.far_map.origin_m) / texel;  // texel centres at whole numbers
  float last = u.far_map.resolution - 1.0;
  float inside = min(min(p.x, p.y), min(last - p.x, last - p.y));
  float window = clamp(inside / u.far_map.fade_texels, 0.0, 1.0);
  return window * clamp(sample_m / texel - 1.0, 0.0, 1.0);
}

// Where the map is read at xz: texel (col, row)'s centre at origin + (col, row)·S/N.
vec2 far_map_uv(vec2 xz) {
  return (xz - u.far_map.origin_m) / u.far_map.size_m + 0.5 / u.far_map.resolution;
}

// The VR-GIS paper's eq. 7 with weights whose squares sum to one: two independent fields of equal
// variance blend into one of the same variance (the printed (1 − R)·a + R·b has half of it at
// R = 1/2, a calm band where the blend is). Returns the two weights.
vec2 preserving_weights(float ratio) {
  vec2 w = vec2(1.0 - ratio, ratio);
  return w / length(w);
}

// How much of a cascade is read through the hex tiles (R.14): the far-field ratio where a tile
// spans at least 4 samples (pixels or vertices, `sample_m` apart), none below 2: smaller tiles
// would give each sample its own random offset, noise instead of the filtered texture, and the
// repetition of so short a period is texture, not a lattice the eye picks out.
float hex_ratio(float ratio, float patch_size_m, float sample_m) {
  float tile_m = patch_size_m / OCEAN_RENDER_HEX_TILES;
  return ratio * clamp(0.5 * tile_m / max(sample_m, 1e-3) - 1.0, 0.0, 1.0);
}

// The three tiles (vertices of a triangle grid of OCEAN_RENDER_HEX_TILES tiles per cascade
// period) around uv, their random offsets in [0, 1)², and weights normalised for the
// variance-preserving blend Σ w_i·x_i with Σ w_i² = 1 (R.14).
struct HexTaps {
  vec2 offset[3];
  vec3 weight;
};
vec2 tile_offset(ivec2 v, int cascade) {
  uint h = far_hash(uint(v.x) ^ far_hash(uint(v.y) + uint(cascade) * 0x9e3779b9u));
  return vec2(float(h & 0xffffu), float(h >> 16u)) / 65536.0;
}
HexTaps hex_taps(vec2 uv, int cascade) {
  // 2√3 makes the triangles' side 1/OCEAN_RENDER_HEX_TILES of the period (Heitz & Neyret 2018).
  vec2 skewed =
      mat2(1.0, 0.0, -0.57735027, 1.15470054) * (uv * 3.46410162 * OCEAN_RENDER_HEX_TILES);
  ivec2 base = ivec2(floor(skewed));
  vec3 t = vec3(fract(skewed), 0.0);
  t.z = 1.0 - t.x - t.y;
  HexTaps taps;
  vec3 w;
  if (t.z > 0.0) {
    w = vec3(t.z, t.y, t.x);
    taps.offset[0] = tile_offset(base, cascade);
    taps.offset[1] = tile_offset(base + ivec2(0, 1), cascade);
    taps.offset[2] = tile_offset(base + ivec2(1, 0), cascade);
  } else {
    w = vec3(-t.z, 1.0 - t.y, 1.0 - t.x);
    taps.offset[0] = tile_offset(base + ivec2(1, 1), cascade);
    taps.offset[1] = tile_offset(base + ivec2(1, 0), cascade);
    taps.offset[2] = tile_offset(base + ivec2(0, 1), cascade);
  }
  w = w * w * w;  // sharpened (Mikkelsen 2022): most of a tile shows one offset
  taps.weight = w / length(w);
  return taps;
}

#endif
