// local_layer.glsl — the local layer (ocean/waves.hpp; docs/rendering.md R.19): wakes and
// waveforms over a square world area, composited into the cascades' sum where the layer covers
// the surface. Its texture array holds, per cell, layer 0: the layer's (Dx, h, Dz), added to the
// cascades' displacement; layer 1: what the layer changes in the surface's shading, the slope
// difference Δs and the added foam Δf (R.19), added to the cascades' slopes and foam. Both fade
// to zero towards the area's border with the layer's soft edge (docs/waves.md W.9), and the
// lookups return zero outside the area.
#ifndef OCEAN_RENDER_LOCAL_LAYER_GLSL
#define OCEAN_RENDER_LOCAL_LAYER_GLSL

#include "render_common.glsl"

layout(set = 0, binding = OCEAN_RENDER_BINDING_LOCAL) uniform sampler2DArray local_layer;

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
  return textureLod(local_layer, vec3(local_uv(xz), 0.0), 0.0).xyz;
}

// The layer's change to the surface gradient (as normal x/y and z/y, the cascades' `slope`) and
// the foam it adds, bilinear between cells (R.19). Zero outside the area.
void local_shade(vec2 xz, out vec2 slope, out float foam) {
  slope = vec2(0.0);
  foam = 0.0;
  if (!local_covers(xz)) return;
  vec4 t = textureLod(local_layer, vec3(local_uv(xz), 1.0), 0.0);
  slope = t.xy;
  foam = clamp(t.z, 0.0, 1.0);
}

#endif
