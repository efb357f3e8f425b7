// src/waves/damping.cpp — the damping of the sea's bands by a world-space mask and a bathymetry
// (W.12–W.13) and their breaking where the water is too shallow to carry them (W.25–W.27):
// placement and sampling of the maps, validation, and the per-band weights that the height
// queries (and, per pixel, a renderer) multiply each cascade by.
//
// This work is based on:
// - McCowan (1894), "On the highest wave of permanent type": a solitary wave breaks at H/d = 0.78.
// - Battjes & Janssen (1978), "Energy loss and set-up due to breaking of random waves": the
//   heights as a Rayleigh distribution truncated at H_max = γ·d, the fraction of breaking waves
//   Q_b the root of (1 − Q_b)/ln Q_b = −(H_rms/H_max)².
// - Longuet-Higgins (1952), "On the statistical distribution of the heights of sea waves":
//   H_rms = √(8·m0) for a narrow-band Gaussian sea.
#include <algorithm>
#include <array>
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
  if (!p.band_variances_m2.empty() && p.band_variances_m2.size() != k.size()) {
    return invalid_argument("damping has " + std::to_string(p.band_variances_m2.size()) +
                            " band variances for " + std::to_string(k.size()) +
                            " band wavenumbers: one per band, or none");
  }
  for (std::size_t i = 0; i < p.band_variances_m2.size(); ++i) {
    const std::string name = "band_variances_m2[" + std::to_string(i) + "]";
    if (Status s = require_finite(name, p.band_variances_m2[i]); !s.ok()) return s;
    if (Status s = require_in_range(name, p.band_variances_m2[i], 0.0, 1e6); !s.ok()) return s;
  }
  if (Status s = require_in_range("breaking_index", p.breaking_index, 0.3, 1.5); !s.ok()) return s;
  if (p.bathymetry) {
    if (Status s = validate_placement("bathymetry", *p.bathymetry); !s.ok()) return s;
    // Negative: land, its height above the mean sea level (W.28).
    if (Status s = validate_values("bathymetry", *p.bathymetry->map, -kMaxLandHeight_m,
                                   std::numeric_limits<double>::max(),
                                   "a depth (finite, m; land down to -1e4)");
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

double breaking_fraction(double b) {
  if (!(b > 0.0)) return 0.0;
  if (b >= 1.0) return 1.0;
  // (W.26) in y = ln Q_b: f(y) = e^y − 1 − b²·y = 0. f is convex, positive at y = −1/b² and
  // negative just below its trivial root y = 0, so Newton's steps from −1/b² rise monotonically
  // to the root between without overshooting it (and without e^y underflowing to a wrong root
  // where Q_b ≈ e^{−1/b²} is below the smallest double).
  const double b2 = b * b;
  double y = -1.0 / b2;
  for (int i = 0; i < 200; ++i) {
    const double f = std::exp(y) - 1.0 - b2 * y;
    const double step = f / (std::exp(y) - b2);  // f' < 0 left of the root
    y -= step;
    if (std::abs(step) <= 1e-15 * std::abs(y)) break;
  }
  return std::exp(y);
}

double Damping::depth_weights(double x, double z, std::span<double> out) const {
  const double inf = std::numeric_limits<double>::infinity();
  const double mask = params_.mask ? sample(*params_.mask, x, z, 1.0) : 1.0;
  const double depth = params_.bathymetry ? sample(*params_.bathymetry, x, z, inf) : inf;
  for (std::size_t c = 0; c < band_count(); ++c) {
    const double k = params_.band_wavenumbers_radpm[c];
    const double water = std::max(depth, 0.0);  // land (depth < 0) carries no waves (W.28)
    out[c] = depth_band_weight(k, water, params_.gravity_mps2) * (c == 0 ? 1.0 : mask);  // (W.13)
  }
  return depth;
}

namespace {

// H_rms, H_max and Q_b from the depth and the bands' weights before breaking (W.25–W.27).
Surf surf_of(const DampingParams& p, double depth_m, std::span<const double> w) {
  Surf s;
  s.depth_m = depth_m;
  double m0 = 0.0;  // the local variance of the damped bands
  for (std::size_t c = 0; c < p.band_variances_m2.size(); ++c)
    m0 += w[c] * w[c] * p.band_variances_m2[c];
  s.rms_height_m = std::sqrt(8.0 * m0);
  s.max_height_m = p.breaking_index * std::max(depth_m, 0.0);         // (W.25)
  s.limited_rms_height_m = std::min(s.rms_height_m, s.max_height_m);  // (W.27)
  if (s.rms_height_m > 0.0)
    s.breaking_fraction = breaking_fraction(s.rms_height_m / s.max_height_m);  // (W.26)
  return s;
}

}  // namespace

Surf Damping::surf(double x, double z) const {
  std::array<double, kMaxBands> w{};
  const double depth = depth_weights(x, z, w);
  return surf_of(params_, depth, w);
}

void Damping::band_weights(double x, double z, std::span<double> out) const {
  std::array<double, kMaxBands> w{};
  const double depth = depth_weights(x, z, w);
  double limit = 1.0;
  if (!params_.band_variances_m2.empty()) {
    const Surf s = surf_of(params_, depth, w);
    if (s.rms_height_m > s.max_height_m) limit = s.max_height_m / s.rms_height_m;  // (W.27)
  }
  const std::size_t n = std::min(out.size(), band_count());
  for (std::size_t c = 0; c < n; ++c) out[c] = w[c] * limit;
}

}  // namespace ocean::waves
