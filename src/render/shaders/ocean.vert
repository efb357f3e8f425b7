#version 450
// The ocean patches of the quadtree LOD (Aebi, VR Ocean, §5, eq. 70) and the horizon skirt
// (§5.7): the unit patch mesh scaled and moved per instance, displaced by the sum of the cascades'
// displacement maps (Aebi, VR Ocean, eq. 44; sampling M.7.6). Each cascade's displacement fades
// out where the mesh is too coarse to carry its dominant wavelength, and all of it fades out
// towards the border of the ocean square, where the flat skirt begins (docs/rendering.md R.9,
// R.10). Beyond the far field's D_min (VR-GIS FFT+Perlin, eq. 6) the cascades are read through
// hex tiles with random offsets and cascade 0 blends into the far field's noise (R.13, R.14).
// All weights are functions of the world position and the camera alone, so vertices that two
// patches share get the same displacement and the stitched mesh stays closed.
#include "far_field.glsl"
#include "planet.glsl"
#include "local_layer.glsl"
#include "damping.glsl"

layout(location = 0) in vec2 a_position;  // unit patch [−0.5, 0.5]² (skirt: world x, z)
layout(location = 1) in vec3 a_instance;  // centre x, centre z, size (skirt: 0, 0, 1)
layout(location = 2) in uvec4 a_meta;     // grid x, grid y, level (skirt: OCEAN_RENDER_SKIRT_LEVEL), configuration

layout(location = 0) out vec2 world_xz;     // undisplaced position relative to the origin (R.16)
layout(location = 1) out vec3 world_pos;    // displaced position relative to the origin
layout(location = 2) flat out uint level;

float geometry_weight(int c, float spacing_m) {
  // Full while the vertex spacing is below a quarter of the cascade's dominant wavelength, none
  // at half of it (the mesh's Nyquist limit) (R.9).
  return clamp(2.0 - 4.0 * spacing_m / u.cascades[c].wavelength_m, 0.0, 1.0);
}

void main() {
  vec2 xz = a_instance.xy + a_position * a_instance.z;
  vec2 rel = xz - u.grid_centre_m;
  float half_size = 0.5 * u.ocean_size_m;
  float border = max(abs(rel.x), abs(rel.y));
  float border_weight = clamp((half_size - border) / u.border_fade_m, 0.0, 1.0);  // R.10
  // The spacing a patch at this distance has at most: a node splits while the camera is closer
  // than τ·s (eq. 57), so a leaf at distance d has s ≤ d/τ·2 and spacing s/V.
  float d = length(vec3(xz.x, 0.0, xz.y) - eye_position());
  float spacing = max(2.0 * d / (u.lod_scale * u.vertices), 1e-3);
  vec3 displacement = vec3(0.0);
  int cascades = int(u.cascade_count);
  if (border_weight > 0.0 && u.local.calm < 0.5) {
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
      if (hex < 1.0) plain = textureLod(displacement_map, vec3(uv, float(c)), 0.0).xyz;
      if (hex > 0.0) {
        HexTaps taps = hex_taps(uv, c);
        for (int i = 0; i < 3; ++i)
          tiled += taps.weight[i] *
                   textureLod(displacement_map, vec3(uv + taps.offset[i], float(c)), 0.0).xyz;
      }
      vec3 sim = w * band_weight(damping, c) * (mixing.x * plain + mixing.y * tiled);
      if (c == 0 && ratio > 0.0) {  // cascade 0 becomes the noise (R.13)
        float h, sx, sz;
        vec3 cell = u.far_field.cell_m.xyz;
        vec2 p = noise_xz(xz);
        far_field_noise(u.far_field, p.x, p.y, clamp(2.0 - 4.0 * spacing / cell.x, 0.0, 1.0),
                        clamp(2.0 - 4.0 * spacing / cell.y, 0.0, 1.0),
                        clamp(2.0 - 4.0 * spacing / cell.z, 0.0, 1.0), h, sx, sz);
        sim = blend.x * sim + vec3(0.0, blend.y * h, 0.0);
      }
      displacement += sim;
    }
    displacement *= border_weight;
  }
  displacement += local_displacement(xz);  // wakes and waveforms (R.19)
  world_xz = xz;
  // The planet bends the sea down by d²/(2R) (R.15).
  world_pos = vec3(xz.x + displacement.x, displacement.y - curvature_drop(xz),
                   xz.y + displacement.z);
  level = a_meta.z;
  gl_Position = eye_view_proj() * vec4(world_pos, 1.0);
}
