// The horizon skirt: four trapezoids from the ocean square out to a far square.
//
// Sources: Aebi, VR Ocean, §5.7; docs/lod.md L.10.
#include <cmath>

#include "ocean/lod.hpp"

namespace ocean::lod {

Result<SkirtMesh> build_skirt(double ocean_size_m, double outer_half_extent_m) {
  if (Status s = require_in_range("ocean_size_m", ocean_size_m, kMinOceanSize_m, kMaxOceanSize_m);
      !s.ok()) {
    return s;
  }
  const double inner = 0.5 * ocean_size_m;
  const double outer = outer_half_extent_m > 0.0 ? outer_half_extent_m : 10.0 * ocean_size_m;
  if (!(outer > inner) || std::isinf(outer)) {
    return invalid_argument("outer_half_extent_m = " + format_number(outer_half_extent_m) +
                            " is out of range: must be > ocean_size_m/2 = " + format_number(inner) +
                            " and finite (or <= 0 for 10·S)");
  }
  SkirtMesh m;
  const auto fi = static_cast<float>(inner);
  const auto fo = static_cast<float>(outer);
  // Pairs (inner, outer) at the west end, the middle and the east end of the north side.
  m.positions_xz = {-fi, fi, -fo, fo, 0.0f, fi, 0.0f, fo, fi, fi, fo, fo};
  m.strip = {0, 1, 2, 3, 4, 5};
  // The strip's triangles (0 1 2), (2 1 3), (2 3 4), (4 3 5), wound to face +y.
  m.triangles = {0, 1, 2, 2, 1, 3, 2, 3, 4, 4, 3, 5};
  m.rotations = {{{1.0f, 0.0f}, {0.0f, 1.0f}, {-1.0f, 0.0f}, {0.0f, -1.0f}}};
  return m;
}

}  // namespace ocean::lod
