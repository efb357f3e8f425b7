#version 450
// The sea on a sphere (docs/rendering.md R.30–R.38): the quadtree's patches on the six faces of
// a cube-sphere, each vertex placed relative to its patch's centre (computed in double on the
// CPU relative to the camera) by the single-precision offset of R.38, then displaced: the
// cascades read tri-planarly, heights along the sphere's normal and the projections' horizontal
// displacements in the tangent plane (R.33–R.34). Vertices on a face's edge are the same cube
// point from both faces, so the stitched mesh stays closed across the cube's edges (R.36).
#include "sphere.glsl"

layout(location = 0) in vec2 a_position;  // unit patch [−0.5, 0.5]²
layout(location = 1) in vec4 a_centre;    // patch centre on the sphere, m, relative to the camera
                                          // in local axes; w: side in cube coordinates
layout(location = 2) in vec4 a_cube;      // cube point of the centre (xyz, dyadic)
layout(location = 3) in uvec4 a_meta;     // face, level, configuration, 0

layout(location = 0) out vec3 planet_q;   // undisplaced offset from the camera, planet axes
layout(location = 1) out vec3 world_pos;  // displaced, relative to the camera, local axes
layout(location = 2) out vec3 normal_p;   // the sphere's normal, planet axes
layout(location = 3) out float height_m;  // along the normal
layout(location = 4) flat out uint level;

void main() {
  uint face = a_meta.x;
  vec3 delta = (a_position.x * a_centre.w) * kFaceU[face] + (a_position.y * a_centre.w) * kFaceV[face];
  vec3 offset = u.sphere.radius_m * sphere_offset(a_cube.xyz, delta);
  vec3 rel = a_centre.xyz + to_local(offset);
  vec3 n = normalize(a_cube.xyz + delta);
  vec3 q = to_planet(rel);
  // The mesh's spacing at this distance at most (eq. 57, as ocean.vert): cascades it cannot
  // carry fade out (R.9).
  float spacing = max(2.0 * length(rel) / (u.lod_scale * u.vertices), 1e-3);
  vec3 w = triplanar_weights(n);
  float h = 0.0;
  vec3 d = vec3(0.0);
  int cascades = u.local.calm > 0.5 ? 0 : int(u.cascade_count);  // calm: no cascades
  for (int c = 0; c < cascades; ++c) {
    float g = clamp(2.0 - 4.0 * spacing / u.cascades[c].wavelength_m, 0.0, 1.0);
    if (g <= 0.0 && c > 0) continue;
    for (int a = 0; a < 3; ++a) {
      if (w[a] <= 0.0) continue;
      vec3 s = textureLod(displacement_map, vec3(sphere_uv(q, a, c), float(c)), 0.0).xyz;
      h += g * w[a] * s.y;
      d += g * w[a] * (s.x * kPlaneE1[a] + s.z * kPlaneE2[a]);
    }
  }
  d -= dot(d, n) * n;  // onto the tangent plane (R.34)
  planet_q = q;
  normal_p = n;
  height_m = h;
  world_pos = rel + to_local(h * n + d);
  level = a_meta.y;
  gl_Position = u.view_proj * vec4(world_pos, 1.0);
}
