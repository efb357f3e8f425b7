// src/waves/area.cpp — the layer's square world area: validation, cell centres and the soft edge
// that fades the layer into the sea (W.9).
#include <algorithm>
#include <cmath>

#include "ocean/waves.hpp"

namespace ocean::waves {

Status validate(const LocalArea& area) {
  if (Status s = require_finite("local_area.origin_m[0]", area.origin_m[0]); !s.ok()) return s;
  if (Status s = require_finite("local_area.origin_m[1]", area.origin_m[1]); !s.ok()) return s;
  if (Status s = require_positive("local_area.size_m", area.size_m); !s.ok()) return s;
  if (Status s = require_in_range("local_area.size_m", area.size_m, 1e-3, 1e6); !s.ok()) return s;
  if (Status s = require_in_range("local_area.resolution", area.resolution, kMinLocalResolution,
                                  kMaxLocalResolution);
      !s.ok()) {
    return s;
  }
  return require_in_range("local_area.edge_fraction", area.edge_fraction, 0.0, 0.5);
}

std::array<double, 2> cell_centre(const LocalArea& area, int col, int row) {
  const double cell = area.size_m / area.resolution;
  return {area.origin_m[0] + (col + 0.5) * cell, area.origin_m[1] + (row + 0.5) * cell};
}

double edge_weight(const LocalArea& area, double x, double z) {
  const double dx = std::min(x - area.origin_m[0], area.origin_m[0] + area.size_m - x);
  const double dz = std::min(z - area.origin_m[1], area.origin_m[1] + area.size_m - z);
  const double d = std::min(dx, dz);
  if (!(d > 0.0)) return 0.0;
  const double band = area.edge_fraction * area.size_m;
  if (d >= band) return 1.0;
  const double t = d / band;
  return t * t * (3.0 - 2.0 * t);  // (W.9)
}

}  // namespace ocean::waves
