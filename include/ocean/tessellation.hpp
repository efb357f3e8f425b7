// ocean/tessellation.hpp — the renderer's second mesh mode: VR-GIS FFT+Perlin's view-dependent
// tessellation (§II, Algorithm 1) instead of the quadtree of ocean/lod.hpp. A base grid of
// quads covers the ocean square; the GPU's tessellation stages subdivide each quad by a level
// that falls with the distance d from the eye's projection onto the sea,
// LOD = N − d/D_span, Tess = sin(LOD·π/(2N))·N (docs/rendering.md R.40). The outer level of each
// edge is the level at the edge's midpoint, so both quads sharing an edge tessellate it alike and
// the mesh has no T-junction cracks (R.42); Algorithm 1 as printed (every outer level the quad
// centre's) stays selectable for comparison.
//
// Contract: plain data and pure functions, no allocation except tessellation_levels' result;
// the same level function (src/render/shaders/tessellation.h) runs in the tessellation control
// shader, so what these functions return is what the GPU uses, up to the GPU's sine.
#pragma once

#include <array>
#include <cstdint>
#include <string_view>
#include <vector>

#include "ocean/core.hpp"
#include "ocean/names.hpp"

namespace ocean::render {

/// How the renderer builds the sea's mesh.
enum class MeshMode : std::uint8_t {
  quadtree,      ///< the quadtree's patches with stitched edges (ocean/lod.hpp; the default)
  tessellation,  ///< a base grid subdivided by the GPU (needs tessellation shaders)
};
/// The names of the mesh modes in flags and messages.
inline constexpr std::array<EnumName<MeshMode>, 2> kMeshModeNames{{
    {MeshMode::quadtree, "quadtree"},
    {MeshMode::tessellation, "tessellation"},
}};
/// The mode named `name`; invalid_argument listing the names otherwise.
Result<MeshMode> parse_mesh_mode(std::string_view name);

/// Algorithm 1's parameters (View::tessellation). In tessellation mode RenderStats::patches
/// counts the base quads drawn and RenderStats::triangles the skirt's only (the tessellator's
/// output is not counted).
struct TessellationParams {
  MeshMode mesh = MeshMode::quadtree;
  int base_quads = 64;       ///< quads per side of the base grid over the ocean square, [1, 256]
  double max_level = 32;     ///< N: the level at the eye's projection, [1, 64] and ≤ the device's
  double span_m = 0.0;       ///< D_span, m: LOD falls by one per D_span; ≤ 0: S/(2N) (0 at S/2)
  bool shared_edges = true;  ///< false: every outer level the quad's own (cracks, as printed)
};
/// invalid_argument naming the field for values outside the ranges above or non-finite ones.
Status validate(const TessellationParams& params);

/// Algorithm 1, lines 4–5 (R.40): the level at a distance d ≥ 0 m from the eye's projection,
/// at least 1 (a quad is never subdivided into less than itself).
float tessellation_level(float distance_m, float max_level, float span_m);

/// One base quad's levels in the quad domain's order: outer[0] the edge x = x0 (u = 0),
/// outer[1] z = z0 (v = 0), outer[2] x = x0 + cell, outer[3] z = z0 + cell; inner = Tess/2.
struct QuadLevels {
  std::array<float, 4> outer{};
  float inner = 1.0f;
};
/// A base grid as the GPU draws it: quads × quads cells of `cell_m` from the corner
/// (x0, z0), and the eye's projection (x, z), all in the same frame.
struct TessellationGrid {
  std::array<float, 2> corner_m{};
  float cell_m = 1.0f;
  int quads = 1;
  std::array<float, 2> eye_m{};
};
/// The levels of every quad of `grid`, row-major (index j·quads + i, i along x): the
/// tessellation control shader's computation on the CPU. `params` must validate.
std::vector<QuadLevels> tessellation_levels(const TessellationParams& params,
                                            const TessellationGrid& grid);
/// D_span for an ocean square of side S: `params.span_m`, or S/(2N) where that is ≤ 0.
double tessellation_span_m(const TessellationParams& params, double ocean_size_m);

}  // namespace ocean::render
