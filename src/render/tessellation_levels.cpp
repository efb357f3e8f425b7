// ocean/tessellation.hpp on the CPU: the mesh modes' names, the parameters' checks and the levels
// of VR-GIS FFT+Perlin's Algorithm 1 (docs/rendering.md R.40–R.42) through the same function the
// tessellation control shader runs (shaders/tessellation.h), so a test of these levels is a test
// of the GPU's.
//
// This work is based on: VR-GIS FFT+Perlin, §II, Algorithm 1 (the level); Moreton (2001),
// "Watertight tessellation using forward differencing" (levels that are functions of the edge).
#include <cmath>

#include "ocean/tessellation.hpp"
#include "tessellation_push.hpp"

namespace ocean::render {

Result<MeshMode> parse_mesh_mode(std::string_view name) {
  if (std::optional<MeshMode> m = value_of(kMeshModeNames, name)) return *m;
  return invalid_argument("mesh = " + excerpt(name) + " is not a mesh mode: must be " +
                          name_list(kMeshModeNames, ", ", " or "));
}

Status validate(const TessellationParams& p) {
  if (p.mesh != MeshMode::quadtree && p.mesh != MeshMode::tessellation)
    return invalid_argument("tessellation.mesh is not a mesh mode");
  if (p.base_quads < 1 || p.base_quads > OCEAN_TESS_MAX_QUADS)
    return invalid_argument("tessellation.base_quads = " + std::to_string(p.base_quads) +
                            " must be in [1, " + std::to_string(OCEAN_TESS_MAX_QUADS) + "]");
  if (Status s = require_in_range("tessellation.max_level", p.max_level, 1.0, 64.0); !s.ok())
    return s;
  if (!std::isfinite(p.span_m))
    return invalid_argument("tessellation.span_m must be finite (<= 0: the default)");
  return {};
}

float tessellation_level(float distance_m, float max_level, float span_m) {
  return shader::tess_level(distance_m, max_level, span_m);
}

double tessellation_span_m(const TessellationParams& params, double ocean_size_m) {
  return params.span_m > 0.0 ? params.span_m : ocean_size_m / (2.0 * params.max_level);
}

shader::TessellationPush tessellation_push(const TessellationParams& params,
                                           const TessellationGrid& grid) {
  return {.origin_m = {grid.corner_m[0], grid.corner_m[1]},
          .cell_m = grid.cell_m,
          .max_level = static_cast<float>(params.max_level),
          .eye_m = {grid.eye_m[0], grid.eye_m[1]},
          .span_m = static_cast<float>(
              tessellation_span_m(params, static_cast<double>(grid.cell_m) * grid.quads)),
          .shared_edges = params.shared_edges ? 1.0f : 0.0f};
}

std::vector<QuadLevels> tessellation_levels(const TessellationParams& params,
                                            const TessellationGrid& grid) {
  const shader::TessellationPush push = tessellation_push(params, grid);
  std::vector<QuadLevels> levels(static_cast<std::size_t>(grid.quads) *
                                 static_cast<std::size_t>(grid.quads));
  for (int j = 0; j < grid.quads; ++j)
    for (int i = 0; i < grid.quads; ++i) {
      QuadLevels& q = levels[static_cast<std::size_t>(j * grid.quads + i)];
      shader::tess_patch_levels(i, j, push, q.outer[0], q.outer[1], q.outer[2], q.outer[3],
                                q.inner);
    }
  return levels;
}

}  // namespace ocean::render
