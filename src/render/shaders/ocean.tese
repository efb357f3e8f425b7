#version 450
// The tessellated mesh's vertices (docs/rendering.md R.40–R.42): a generated point (u, v) of
// base quad (i, j) lies at grid coordinates (i + u, j + v), so a point on an edge that two quads
// share — the tessellator gives both the same parameters there when the edge's level is the
// same (Vulkan's tessellation invariance rules) — lands on the same position, bit for bit, and
// gets the same displacement (ocean_displacement.glsl, as the quadtree's ocean.vert). The mesh
// spacing that fades the cascades (R.9) is the cell over half the level there: the inner level,
// the coarser of the two.
#include "ocean_displacement.glsl"
#include "tessellation.h"

layout(quads, fractional_odd_spacing, ccw) in;

layout(push_constant, std430) uniform TessellationBlock {
  layout(offset = OCEAN_TESS_PUSH_OFFSET) TessellationPush tess;
};

layout(location = 0) patch in uvec2 patch_cell;

layout(location = 0) out vec2 world_xz;   // undisplaced position relative to the origin (R.16)
layout(location = 1) out vec3 world_pos;  // displaced position relative to the origin
layout(location = 2) flat out uint level;

void main() {
  precise float gx = float(patch_cell.x) + gl_TessCoord.x;
  precise float gz = float(patch_cell.y) + gl_TessCoord.y;
  precise vec2 xz = tess.origin_m + vec2(gx, gz) * tess.cell_m;
  float tess_here = tess_level_at(gx, gz, tess);
  vec3 displacement = ocean_displacement(xz, tess.cell_m / max(0.5 * tess_here, 1.0));
  world_xz = xz;
  // The planet bends the sea down by d²/(2R) (R.15).
  world_pos = vec3(xz.x + displacement.x, displacement.y - curvature_drop(xz),
                   xz.y + displacement.z);
  // The LOD colours: one colour per halving of the level below N.
  level = uint(clamp(log2(tess.max_level / tess_here), 0.0, 8.0));
  gl_Position = u.view_proj * vec4(world_pos, 1.0);
}
