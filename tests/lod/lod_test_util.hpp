// Helpers of the LOD tests: the selected patches as a triangle soup on the finest vertex lattice.
#pragma once

#include <cstdint>
#include <vector>

#include "ocean/lod.hpp"

namespace lod_test {

/// A lattice point: world = grid corner + (i, j)·S/(W·V), exact integers.
struct LatticeTriangle {
  std::int64_t x[3], z[3];
};

/// Every triangle of every instance, on the lattice of the finest vertex spacing.
inline std::vector<LatticeTriangle> triangle_soup(const ocean::lod::LodSelection& sel,
                                                  const ocean::lod::PatchMeshes& meshes) {
  std::vector<LatticeTriangle> out;
  const int v = meshes.vertices;
  for (const ocean::lod::PatchInstance& pi : sel.instances) {
    const std::int64_t delta = std::int64_t{1} << (sel.max_level - pi.level);
    const std::int64_t ox = pi.grid_x * delta * v, oz = pi.grid_y * delta * v;
    const auto& idx = meshes.indices[pi.config];
    for (std::size_t t = 0; t < idx.size(); t += 3) {
      LatticeTriangle tri{};
      for (int k = 0; k < 3; ++k) {
        const int id = idx[t + static_cast<std::size_t>(k)];
        tri.x[k] = ox + (id % (v + 1)) * delta;
        tri.z[k] = oz + (id / (v + 1)) * delta;
      }
      out.push_back(tri);
    }
  }
  return out;
}

/// Twice the signed area with the +y-facing orientation positive ((b − a) × (c − a)).y.
inline std::int64_t twice_area_up(const LatticeTriangle& t) {
  const std::int64_t ux = t.x[1] - t.x[0], uz = t.z[1] - t.z[0];
  const std::int64_t vx = t.x[2] - t.x[0], vz = t.z[2] - t.z[0];
  return uz * vx - ux * vz;
}

}  // namespace lod_test
