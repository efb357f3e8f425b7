#version 450
// The tessellated mesh's levels (VR-GIS FFT+Perlin, Algorithm 1; docs/rendering.md R.40–R.42):
// each base quad's outer levels from the midpoints of its own edges and its inner level from its
// centre, by tessellation.h's tess_patch_levels — the function the C++ (and its test) runs.
#include "tessellation.h"

layout(vertices = 1) out;

layout(push_constant, std430) uniform TessellationBlock {
  layout(offset = OCEAN_TESS_PUSH_OFFSET) TessellationPush tess;
};

layout(location = 0) in uvec2 cell[];
layout(location = 0) patch out uvec2 patch_cell;

void main() {
  patch_cell = cell[0];
  float o0, o1, o2, o3, inner;
  tess_patch_levels(int(cell[0].x), int(cell[0].y), tess, o0, o1, o2, o3, inner);
  gl_TessLevelOuter[0] = o0;
  gl_TessLevelOuter[1] = o1;
  gl_TessLevelOuter[2] = o2;
  gl_TessLevelOuter[3] = o3;
  gl_TessLevelInner[0] = inner;
  gl_TessLevelInner[1] = inner;
}
