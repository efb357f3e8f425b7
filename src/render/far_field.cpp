// The far field's distance range (ocean/far_field.hpp, docs/rendering.md R.13); the noise, its fit
// and its CPU reference are src/sim/far_noise.cpp.
//
// This work is based on: VR-GIS FFT+Perlin ("CUDA concurrent kernels: FFT + Perlin noise ocean
// for a VR-GIS platform"), §III: the Hermite ratio (eq. 6).
#include "ocean/far_field.hpp"

#include <algorithm>
#include <cmath>
#include <string>

namespace ocean::render {

Status validate(const FarFieldRange& range) {
  if (!std::isfinite(range.near_m) || !std::isfinite(range.far_m) || range.near_m < 0.0 ||
      range.far_m < 0.0)
    return invalid_argument("far field range " + std::to_string(range.near_m) + ", " +
                            std::to_string(range.far_m) +
                            " must be finite distances >= 0 m (D_min, D_max)");
  if (range.near_m >= range.far_m)
    return invalid_argument("far field range: D_min = " + std::to_string(range.near_m) +
                            " m must be below D_max = " + std::to_string(range.far_m) + " m");
  return {};
}

double far_field_ratio(const FarFieldRange& range, double distance_m) {
  double t = (distance_m - range.near_m) / (range.far_m - range.near_m);
  t = std::clamp(t, 0.0, 1.0);
  return t * t * (3.0 - 2.0 * t);  // VR-GIS FFT+Perlin, eq. 6
}

}  // namespace ocean::render
