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

Result<FarNoiseConfig> far_noise_window(const FarFieldRange& range, int resolution, double x_m,
                                        double z_m) {
  if (Status s = validate(range); !s.ok()) return s;
  if (resolution < kFarNoiseMinResolution || resolution > 4096)
    return invalid_argument("far-field noise map resolution " + std::to_string(resolution) +
                            " is out of range: must be 0 (off) or in [" +
                            std::to_string(kFarNoiseMinResolution) + ", 4096]");
  // R.13b-3: S/2 = D_max + (snap + fade + 1)·S/N.
  constexpr int kMargin = 2 * (kFarNoiseSnapTexels + kFarNoiseFadeTexels + 1);
  const double size = 2.0 * range.far_m / (1.0 - static_cast<double>(kMargin) / resolution);
  if (!(size <= 1e6))
    return invalid_argument("far-field noise map: a window of " + std::to_string(size) +
                            " m for D_max = " + std::to_string(range.far_m) +
                            " m exceeds the simulation's 1e6 m");
  FarNoiseConfig window{.resolution = resolution, .size_m = std::max(size, 1.0)};
  window.origin_m = far_noise_origin(window, x_m, z_m);
  return window;
}

std::array<double, 2> far_noise_origin(const FarNoiseConfig& window, double x_m, double z_m) {
  const double snap = kFarNoiseSnapTexels * window.size_m / window.resolution;
  const auto corner = [&](double c) { return snap * std::floor((c - 0.5 * window.size_m) / snap); };
  return {corner(x_m), corner(z_m)};  // R.13b-2
}

}  // namespace ocean::render
