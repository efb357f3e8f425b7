// src/waves/waveform.cpp — a pre-authored height map placed in the world (Mitchell 2005, §3.4):
// validation and bilinear sampling under its rotation, size and amplitude (W.10).
#include <algorithm>
#include <cmath>
#include <numbers>

#include "ocean/waves.hpp"

namespace ocean::waves {

Status validate(const Waveform& w) {
  if (w.map == nullptr || w.map->rows < 1 || w.map->cols < 1 ||
      w.map->values.size() !=
          static_cast<std::size_t>(w.map->rows) * static_cast<std::size_t>(w.map->cols)) {
    return invalid_argument("waveform has no height map");
  }
  if (Status s = require_finite("x_m", w.x_m); !s.ok()) return s;
  if (Status s = require_finite("z_m", w.z_m); !s.ok()) return s;
  if (Status s = require_positive("size_m", w.size_m); !s.ok()) return s;
  if (Status s = require_in_range("size_m", w.size_m, 1e-3, 1e6); !s.ok()) return s;
  if (Status s = require_finite("amplitude_m", w.amplitude_m); !s.ok()) return s;
  if (Status s = require_in_range("amplitude_m", w.amplitude_m, -1e3, 1e3); !s.ok()) return s;
  return require_finite("rotation_deg", w.rotation_deg);
}

double waveform_height(const Waveform& w, double x, double z) {
  const HeightMap& map = *w.map;
  const double r = w.rotation_deg * std::numbers::pi / 180.0;
  const double dx = x - w.x_m, dz = z - w.z_m;
  // World offset into the map's frame: turn by −rotation.
  const double ux = dx * std::cos(r) + dz * std::sin(r);
  const double uz = -dx * std::sin(r) + dz * std::cos(r);
  const double width = w.size_m, depth = w.size_m * map.rows / map.cols;
  // Sample coordinates: cell c covers [c, c + 1) of the map, its value sits at c + ½.
  const double u = (ux / width + 0.5) * map.cols - 0.5;
  const double v = (uz / depth + 0.5) * map.rows - 0.5;
  if (!(u >= -0.5 && u <= map.cols - 0.5 && v >= -0.5 && v <= map.rows - 0.5)) return 0.0;
  const double uc = std::clamp(u, 0.0, map.cols - 1.0), vc = std::clamp(v, 0.0, map.rows - 1.0);
  const int c0 = std::min(static_cast<int>(uc), map.cols - 1);
  const int r0 = std::min(static_cast<int>(vc), map.rows - 1);
  const int c1 = std::min(c0 + 1, map.cols - 1), r1 = std::min(r0 + 1, map.rows - 1);
  const double fc = uc - c0, fr = vc - r0;
  const auto at = [&](int row, int col) {
    return static_cast<double>(
        map.values[static_cast<std::size_t>(row) * static_cast<std::size_t>(map.cols) +
                   static_cast<std::size_t>(col)]);
  };
  const double top = at(r0, c0) * (1.0 - fc) + at(r0, c1) * fc;
  const double bottom = at(r1, c0) * (1.0 - fc) + at(r1, c1) * fc;
  return w.amplitude_m * (top * (1.0 - fr) + bottom * fr);  // (W.10)
}

}  // namespace ocean::waves
