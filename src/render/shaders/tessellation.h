// tessellation.h — the tessellated mesh's levels (docs/rendering.md R.40–R.42), one source for
// the C++ (src/render/tessellation.cpp, ocean/tessellation.hpp, the tests) and the tessellation
// control shader (ocean.tesc) and evaluation shader (ocean.tese). Written in the subset C++ and
// GLSL share: 32-bit int and float scalars, `OCEAN_FN` for `inline`, `OCEAN_OUT` for
// out-parameters, `OCEAN_IN` for a struct passed in, `OCEAN_PRECISE` for GLSL's `precise`.
//
// Sources: VR-GIS FFT+Perlin (§II, Algorithm 1: LOD_i = N − d/D_span, Tess = sin(LOD_i·π/(2N))·N,
// OutTess = Tess, InTess = Tess/2); Moreton, H. (2001) "Watertight tessellation using forward
// differencing" (a shared edge is tessellated alike from both sides when its level is a function
// of the edge alone).
#ifndef OCEAN_TESSELLATION_H
#define OCEAN_TESSELLATION_H

#include "render_shared.h"

#ifdef __cplusplus
#include <algorithm>
#include <cmath>
namespace ocean::render::shader {
using std::max;
using std::min;
using std::sin;
using std::sqrt;
#define OCEAN_FN inline
#define OCEAN_OUT(T) T&
#define OCEAN_IN(T) const T&
#define OCEAN_PRECISE
#else
#define OCEAN_FN
#define OCEAN_OUT(T) out T
#define OCEAN_IN(T) T
#define OCEAN_PRECISE precise
#endif

// The most quads per side of the base grid (the per-frame cell list holds this many squared).
#define OCEAN_TESS_MAX_QUADS 256
// Where the tessellation stages' push constants start: after the sky pass's and the seabed's
// range (SkyPush, 64 bytes), which the fragment stage owns.
#define OCEAN_TESS_PUSH_OFFSET 64

// The base grid and Algorithm 1's parameters, pushed to the tessellation stages (std430).
// Positions are relative to the frame's origin O (R.16).
struct TessellationPush {
  vec2 origin_m;       // the grid's corner of smallest x and z
  float cell_m;        // side of one base quad
  float max_level;     // N: the level at the projection point
  vec2 eye_m;          // P_proj: the eye projected onto the sea plane (x, z)
  float span_m;        // D_span: the distance over which LOD drops by one
  float shared_edges;  // 1: each outer level from its own edge (R.42); 0: the seed's, per quad
};

// Algorithm 1, lines 4–5 (R.40): the level at a distance d from P_proj, at least 1.
OCEAN_FN float tess_level(float d_m, float max_level, float span_m) {
  float lod = min(max(max_level - d_m / span_m, 0.0f), max_level);
  return max(sin(lod * (1.5707963f / max_level)) * max_level, 1.0f);
}

// The level at grid coordinates (gx, gz) (base quads from the grid's corner; quad (i, j) spans
// [i, i + 1] × [j, j + 1]). Every operation is `precise`, so equal coordinates give equal levels
// however the compiler inlines it.
OCEAN_FN float tess_level_at(float gx, float gz, OCEAN_IN(TessellationPush) p) {
  OCEAN_PRECISE float x = p.origin_m.x + gx * p.cell_m;
  OCEAN_PRECISE float z = p.origin_m.y + gz * p.cell_m;
  OCEAN_PRECISE float dx = x - p.eye_m.x;
  OCEAN_PRECISE float dz = z - p.eye_m.y;
  OCEAN_PRECISE float level = tess_level(sqrt(dx * dx + dz * dz), p.max_level, p.span_m);
  return level;
}

// Quad (i, j)'s levels in the order of the quad domain (R.41, R.42): outer0 the edge u = 0
// (x = i), outer1 v = 0 (z = j), outer2 u = 1 (x = i + 1), outer3 v = 1 (z = j + 1); inner is
// Algorithm 1's InTess = Tess/2 at the centre. With shared_edges each outer level is the level at
// its edge's midpoint — a function of the edge alone, so the two quads sharing an edge give it
// the same level and the same vertices; without it every outer level is the centre's Tess
// (Algorithm 1 as printed, which leaves T-junction cracks between quads of different levels).
OCEAN_FN void tess_patch_levels(int i, int j, OCEAN_IN(TessellationPush) p,
                                OCEAN_OUT(float) outer0, OCEAN_OUT(float) outer1,
                                OCEAN_OUT(float) outer2, OCEAN_OUT(float) outer3,
                                OCEAN_OUT(float) inner) {
  float fi = float(i), fj = float(j);
  float centre = tess_level_at(fi + 0.5f, fj + 0.5f, p);
  inner = max(0.5f * centre, 1.0f);
  if (p.shared_edges > 0.5f) {
    outer0 = tess_level_at(fi, fj + 0.5f, p);
    outer1 = tess_level_at(fi + 0.5f, fj, p);
    outer2 = tess_level_at(fi + 1.0f, fj + 0.5f, p);
    outer3 = tess_level_at(fi + 0.5f, fj + 1.0f, p);
  } else {
    outer0 = centre;
    outer1 = centre;
    outer2 = centre;
    outer3 = centre;
  }
}

#ifdef __cplusplus
static_assert(sizeof(TessellationPush) == 32);
}  // namespace ocean::render::shader
#endif
#undef OCEAN_FN
#undef OCEAN_OUT
#undef OCEAN_IN
#undef OCEAN_PRECISE

#endif
