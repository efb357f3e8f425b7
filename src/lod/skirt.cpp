// The horizon skirt: four trapezoids from the ocean square out to a far square, each a grid of
// `segments` × `rings` quads so that a renderer can bend it with the planet's curvature.
//
// Sources: Aebi, VR Ocean, §5.7; docs/lod.md L.10.
#include <cmath>

#include "ocean/lod.hpp"

namespace ocean::lod {

Result<SkirtMesh> build_skirt(double ocean_size_m, double outer_half_extent_m,
                              SkirtTessellation tessellation) {
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
  const int segments = tessellation.segments, rings = tessellation.rings;
  if (segments < 2 || segments % 2 != 0 || rings < 1 || 4 * (segments + 1) * (rings + 1) > 65536) {
    return invalid_argument("skirt tessellation " + std::to_string(segments) + " × " +
                            std::to_string(rings) +
                            " is out of range: segments even ≥ 2, rings ≥ 1, 4·(segments + 1)·"
                            "(rings + 1) ≤ 65536 vertices");
  }
  SkirtMesh m;
  const int row = segments + 1;
  // Ring k lies at the half-extent inner·(outer/inner)^(k/rings) (L.10): a geometric series, so
  // the rings are about as far apart on screen near the square as towards the horizon.
  for (int k = 0; k <= rings; ++k) {
    const double d = k == rings ? outer : inner * std::pow(outer / inner, double(k) / rings);
    for (int i = 0; i <= segments; ++i) {
      const double u = -1.0 + 2.0 * i / segments;  // along the north edge, west to east
      m.positions_xz.push_back(static_cast<float>(u * d));
      m.positions_xz.push_back(static_cast<float>(d));
    }
  }
  // The strip of the coarsest skirt (one ring): (inner, outer) pairs west to east.
  if (rings == 1) {
    for (int i = 0; i <= segments; ++i) {
      m.strip.push_back(static_cast<std::uint16_t>(i));
      m.strip.push_back(static_cast<std::uint16_t>(row + i));
    }
  }
  for (int k = 0; k < rings; ++k) {
    for (int i = 0; i < segments; ++i) {
      const auto a = static_cast<std::uint16_t>(k * row + i);  // inner west corner of the quad
      const auto b = static_cast<std::uint16_t>(a + row), c = static_cast<std::uint16_t>(a + 1);
      const auto e = static_cast<std::uint16_t>(b + 1);
      // (a b c), (c b e): wound to face +y.
      for (std::uint16_t v : {a, b, c, c, b, e}) m.triangles.push_back(v);
    }
  }
  m.rotations = {{{1.0f, 0.0f}, {0.0f, 1.0f}, {-1.0f, 0.0f}, {0.0f, -1.0f}}};
  return m;
}

}  // namespace ocean::lod
