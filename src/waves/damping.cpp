// src/waves/damping.cpp — the damping of the sea's bands by a world-space mask and a bathymetry
// (W.12–W.13): placement and sampling of the maps, validation, and the per-band weights that the
// height queries (and, per pixel, a renderer) multiply each cascade by.
#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <string>

#include "ocean/spectrum.hpp"
#include "ocean/waves.hpp"

namespace ocean::waves {
namespace {

Status validate_placement(const std::string& name, const PlacedMap& placed) {
  if (placed.map == nullptr || placed.map->rows < 1 || placed.map->cols < 1 ||
      placed.map->values.size() !=
          static_cast<std::size_t>(placed.map->rows) * static_cast<std::size_t>(placed.map->cols))
    return invalid_argument(name + ": no map, or its size does not match its rows and columns");
  if (Status s = require_finite(name + ".origin_m[0]", placed.origin_m[0]); !s.ok()) return s;
  if (Status s = require_finite(name + ".origin_m[1]", placed.origin_m[1]); !s.ok()) return s;
  if (Status s = require_positive(name + ".size_m", placed.size_m); !s.ok()) return s;
  return require_in_range(name + ".size_m", placed.size_m, 1e-3, 1e7);
}

// The first value outside [lo, hi] (NaN included), named by its index.
Status validate_values(const std::string& name, const HeightMap& map, double lo, double hi,
                       const char* meaning) {
  for (std::size_t i = 0; i < map.values.size(); ++i) {
    const double v = map.values[i];
    if (!(v >= lo && v <= hi)) {
      std::ostringstream text;
      text << v;
      return invalid_argument(name + " value " + std::to_string(i) + " = " + text.str() +
                              " is not " + meaning);
    }
  }
  return {};
}

}  // namespace

double sample(const PlacedMap& placed, double x, double z, double outside) {
  const HeightMap& m = *placed.map;
  const double cell = placed.size_m / m.cols;
  const double u = (x - placed.origin_m[0]) / cell;  // in columns, 0 at the map's edge
  const double v = (z - placed.origin_m[1]) / cell;
  if (!(u >= 0.0 && u <= m.cols && v >= 0.0 && v <= m.rows)) return outside;
  const double cu = std::clamp(u - 0.5, 0.0, m.cols - 1.0);  // sample centres at c + ½
  const double cv = std::clamp(v - 0.5, 0.0, m.rows - 1.0);
  const int c0 = std::min(static_cast<int>(cu), m.cols - 1), c1 = std::min(c0 + 1, m.cols - 1);
  const int r0 = std::min(static_cast<int>(cv), m.rows - 1), r1 = std::min(r0 + 1, m.rows - 1);
  const double fu = cu - c0, fv = cv - r0;
  const auto at = [&](int r, int c) {
    return static_cast<double>(m.values[static_cast<std::size_t>(r * m.cols + c)]);
  };
  const double top = at(r0, c0) * (1.0 - fu) + at(r0, c1) * fu;
  const double bottom = at(r1, c0) * (1.0 - fu) + at(r1, c1) * fu;
  return top * (1.0 - fv) + bottom * fv;
}

Status validate(const DampingParams& p) {
  if (Status s = require_in_range("gravity_mps2", p.gravity_mps2, 0.1, 100.0); !s.ok()) return s;
  const std::vector<double>& k = p.band_wavenumbers_radpm;
  if (k.empty() || k.size() > kMaxBands) {
    return invalid_argument("damping needs 1 to " + std::to_string(kMaxBands) +
                            " band wavenumbers, not " + std::to_string(k.size()));
  }
  for (std::size_t i = 0; i < k.size(); ++i) {
    const std::string name = "band_wavenumbers_radpm[" + std::to_string(i) + "]";
    if (Status s = require_finite(name, k[i]); !s.ok()) return s;
    if (Status s = require_positive(name, k[i]); !s.ok()) return s;
  }
  if (p.mask) {
    if (Status s = validate_placement("damping mask", *p.mask); !s.ok()) return s;
    if (Status s = validate_values("damping mask", *p.mask->map, 0.0, 1.0, "in [0, 1]"); !s.ok())
      return s;
  }
  if (p.bathymetry) {
    if (Status s = validate_placement("bathymetry", *p.bathymetry); !s.ok()) return s;
    if (Status s = validate_values("bathymetry", *p.bathymetry->map, 0.0,
                                   std::numeric_limits<double>::max(), "a depth (finite, >= 0 m)");
        !s.ok())
      return s;
  }
  return {};
}

double depth_band_weight(double wavenumber_radpm, double depth_m, double gravity_mps2) {
  const double omega = std::sqrt(gravity_mps2 * wavenumber_radpm);  // deep-water ω of the band
  return std::sqrt(tma_depth_factor(omega, depth_m, gravity_mps2, DepthFactor::exact));  // (W.12)
}

Result<Damping> Damping::make(DampingParams params) {
  if (Status s = validate(params); !s.ok()) return s;
  Damping d;
  d.params_ = std::move(params);
  return d;
}

void Damping::band_weights(double x, double z, std::span<double> out) const {
  const double inf = std::numeric_limits<double>::infinity();
  const double mask = params_.mask ? sample(*params_.mask, x, z, 1.0) : 1.0;
  const double depth = params_.bathymetry ? sample(*params_.bathymetry, x, z, inf) : inf;
  const std::size_t n = std::min(out.size(), band_count());
  for (std::size_t c = 0; c < n; ++c) {
    const double k = params_.band_wavenumbers_radpm[c];
    out[c] = depth_band_weight(k, depth, params_.gravity_mps2) * (c == 0 ? 1.0 : mask);  // (W.13)
  }
}

}  // namespace ocean::waves
