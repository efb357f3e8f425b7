// ocean_displacement.glsl — the displacement of the sea surface at an undisplaced position, shared
// by the mesh modes' vertex stages: ocean.vert (the quadtree patches and the skirt, and with
// OCEAN_MOTION the previous frame's, R.26) and ocean.tese (the tessellated grid, R.40–R.42): the
// cascades of displacement.glsl (R.9, R.13, R.14, R.24) faded at the border of the ocean square
// (R.10), plus the local layer (R.19); land, where the bathymetry rises above the sea, at its
// height (R.64). A function of the world position, the camera and the mesh spacing there alone,
// so vertices that two patches share get the same displacement and a closed mesh stays closed.
#ifndef OCEAN_DISPLACEMENT_GLSL
#define OCEAN_DISPLACEMENT_GLSL

#include "far_field.glsl"
#include "planet.glsl"
#include "local_layer.glsl"
#include "damping.glsl"
#include "displacement.glsl"

// (Dx, h, Dz) at `xz` (relative to the origin, R.16) for a mesh whose vertex spacing there is
// `spacing` metres, with the cascades read from `map` (the frame's, or the previous frame's).
vec3 ocean_displacement_from(sampler2DArray map, vec2 xz, float spacing) {
  float depth = grid_depth_at(xz);
  if (depth < 0.0) return vec3(0.0, -depth, 0.0);  // land at its height, no waves (R.64)
  vec2 rel = xz - u.grid_centre_m;
  float half_size = 0.5 * u.ocean_size_m;
  float border = max(abs(rel.x), abs(rel.y));
  float border_weight = clamp((half_size - border) / u.border_fade_m, 0.0, 1.0);  // R.10
  vec3 displacement = vec3(0.0);
  if (border_weight > 0.0 && u.local.calm < 0.5)
    displacement = border_weight * sea_displacement(map, xz, spacing);
  return displacement + local_displacement(xz);  // wakes and waveforms (R.19)
}

vec3 ocean_displacement(vec2 xz, float spacing) {
  return ocean_displacement_from(displacement_map, xz, spacing);
}

#endif
