// ocean_displacement.glsl — the displacement of the sea surface at an undisplaced position (R.9,
// R.10, R.13, R.14, R.19, R.24), shared by the mesh modes' vertex stages: ocean.vert (the quadtree
// patches and the skirt) and ocean.tese (the tessellated grid, R.40–R.42). A function of the
// world position, the camera and the mesh spacing there alone, so vertices that two patches
// share get the same displacement and a closed mesh stays closed.
#ifndef OCEAN_DISPLACEMENT_GLSL
#define OCEAN_DISPLACEMENT_GLSL
#include "far_field.glsl"
#include "planet.glsl"
#include "local_layer.glsl"
#include "damping.glsl"

float geometry_weight(int c, float spacing_m) {
  // Full while the vertex spacing is below a quarter of the cascade's dominant wavelength, none
  // at half of it (the mesh's Nyquist limit) (R.9).
  return clamp(2.0 - 4.0 * spacing_m / u.cascades[c].wavelength_m, 0.0, 1.0);
}

// The displacement (Dx, h, Dz) at `xz` (relative to the origin, R.16) for a mesh whose vertex
// spacing there is `spacing` metres: the cascades, faded where the mesh cannot carry them and at
// the border of the ocean square, blended into the far field beyond D_min, plus the local layer.
vec3 ocean_displacement(vec2 xz, float spacing) {
  vec2 rel = xz - u.grid_centre_m;
  float half_size = 0.5 * u.ocean_size_m;
  float border = max(abs(rel.x), abs(rel.y));
  float border_weight = clamp((half_size - border) / u.border_fade_m, 0.0, 1.0);  // R.10
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
  return displacement + local_displacement(xz);  // wakes and waveforms (R.19)
}

#endif
