// local_layer.glsl — the local layer (ocean/waves.hpp; docs/rendering.md R.19): wakes and
// waveforms over a square world area, composited into the cascades' sum where the layer covers
// the surface. The layer carries its own soft edge (docs/waves.md W.9), so it reaches zero at the
// area's border and the lookups clamp to that zero outside.
#ifndef OCEAN_RENDER_LOCAL_LAYER_GLSL
#define OCEAN_RENDER_LOCAL_LAYER_GLSL

#include "render_common.glsl"

layout(set = 0, binding = OCEAN_RENDER_BINDING_LOCAL) uniform sampler2D local_layer;

// Texture coordinate of the undisplaced world point (x, z); cells sit at their centres.
vec2 local_uv(vec2 xz) { return (xz - u.local.origin_m) / u.local.size_m; }

bool local_covers(vec2 xz) {
  vec2 uv = local_uv(xz);
  return u.local.resolution > 0.0 && all(greaterThanEqual(uv, vec2(0.0))) &&
         all(lessThanEqual(uv, vec2(1.0)));
}

// (Dx, h, Dz) of the layer at xz, m; zero outside the area.
vec3 local_displacement(vec2 xz) {
  if (!local_covers(xz)) return vec3(0.0);
  return textureLod(local_layer, local_uv(xz), 0.0).xyz;
}

// The layer's surface gradient (∂h/∂x, ∂h/∂z) and its instantaneous foam from its own Jacobian
// J = (1 + ∂Dx/∂x)(1 + ∂Dz/∂z) − ∂Dx/∂z·∂Dz/∂x (M.7.4's ramp), by central differences one cell
// apart. Zero outside the area.
void local_shade(vec2 xz, out vec2 slope, out float foam) {
  slope = vec2(0.0);
  foam = 0.0;
  if (!local_covers(xz)) return;
  float cell = u.local.size_m / u.local.resolution;
  vec2 uv = local_uv(xz), du = vec2(1.0 / u.local.resolution, 0.0);
  vec3 px = textureLod(local_layer, uv + du.xy, 0.0).xyz;
  vec3 mx = textureLod(local_layer, uv - du.xy, 0.0).xyz;
  vec3 pz = textureLod(local_layer, uv + du.yx, 0.0).xyz;
  vec3 mz = textureLod(local_layer, uv - du.yx, 0.0).xyz;
  vec3 d_dx = (px - mx) / (2.0 * cell), d_dz = (pz - mz) / (2.0 * cell);
  slope = vec2(d_dx.y, d_dz.y);
  float j = (1.0 + d_dx.x) * (1.0 + d_dz.z) - d_dz.x * d_dx.z;
  foam = clamp((u.local.foam_j_start - j) / (u.local.foam_j_start - u.local.foam_j_full), 0.0,
               1.0);
}

#endif
