// The patch mesh and its 16 edge-stitching index buffers.
//
// Sources: Aebi, VR Ocean, §5.3.3–§5.4 (eqs. 65–68); docs/lod.md L.8.
#include <cassert>
#include <string>

#include "ocean/lod.hpp"

namespace ocean::lod {

namespace {

// The 8 boundary vertices of a 3×3 cell, (vx, vy) offsets, walked counter-clockwise in the
// (x, z) plane seen with +z up: SW, S, SE, E, NE, N, NW, W. Odd entries are edge midpoints.
constexpr int kRing[8][2] = {{0, 0}, {1, 0}, {2, 0}, {2, 1}, {2, 2}, {1, 2}, {0, 2}, {0, 1}};
// The edge each midpoint lies on (ring entries 1, 3, 5, 7).
constexpr std::uint8_t kMidpointEdge[4] = {kSouth, kEast, kNorth, kWest};

}  // namespace

std::vector<std::uint16_t> build_patch_indices(int vertices, int config) {
  assert(vertices >= 2 && vertices <= 254 && vertices % 2 == 0);
  assert(config >= 0 && config < kConfigurations);
  const int cells = vertices / 2;
  const int row = vertices + 1;
  std::vector<std::uint16_t> out;
  out.reserve(static_cast<std::size_t>(3 * 8 * cells * cells));
  for (int cy = 0; cy < cells; ++cy) {
    for (int cx = 0; cx < cells; ++cx) {
      // L.8 (Aebi, VR Ocean, eq. 65): only boundary cells inherit the patch's edge flags.
      int cell = 0;
      if (cx == cells - 1) cell |= config & kEast;
      if (cy == cells - 1) cell |= config & kNorth;
      if (cx == 0) cell |= config & kWest;
      if (cy == 0) cell |= config & kSouth;
      // Aebi, VR Ocean, eq. 68.
      auto idx = [&](int vx, int vy) {
        return static_cast<std::uint16_t>((2 * cx + vx) + (2 * cy + vy) * row);
      };
      const std::uint16_t centre = idx(1, 1);
      int kept[8];
      int n = 0;
      for (int k = 0; k < 8; ++k) {
        if (k % 2 == 1 && (cell & kMidpointEdge[k / 2]) != 0) continue;  // stitched midpoint
        kept[n++] = k;
      }
      // Fan around the centre. The ring runs counter-clockwise seen with +z up, which is
      // clockwise seen from +y, so each triangle is (centre, next, this) to face +y.
      for (int i = 0; i < n; ++i) {
        const int* a = kRing[kept[i]];
        const int* b = kRing[kept[(i + 1) % n]];
        out.push_back(centre);
        out.push_back(idx(b[0], b[1]));
        out.push_back(idx(a[0], a[1]));
      }
    }
  }
  return out;
}

Result<PatchMeshes> build_patch_meshes(int vertices) {
  if (vertices < 2 || vertices > 254 || vertices % 2 != 0) {
    return invalid_argument("vertices = " + std::to_string(vertices) +
                            " is out of range: must be an even integer in [2, 254]");
  }
  PatchMeshes m;
  m.vertices = vertices;
  const int row = vertices + 1;
  m.positions_xz.reserve(static_cast<std::size_t>(2 * row * row));
  for (int j = 0; j < row; ++j) {
    for (int i = 0; i < row; ++i) {  // Aebi, VR Ocean, eq. 67
      m.positions_xz.push_back(static_cast<float>(i) / static_cast<float>(vertices) - 0.5f);
      m.positions_xz.push_back(static_cast<float>(j) / static_cast<float>(vertices) - 0.5f);
    }
  }
  for (int c = 0; c < kConfigurations; ++c) {
    m.indices[static_cast<std::size_t>(c)] = build_patch_indices(vertices, c);
  }
  return m;
}

}  // namespace ocean::lod
