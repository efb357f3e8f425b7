// Measuring a Kelvin wake from its heights: the transverse wavelength from the zero crossings of
// the height along the track behind the object (Kelvin 1887; Lighthill, Waves in Fluids, §3.10:
// 2πU²/g). Shared by the tests that measure a wake from a layer's field.
#pragma once

#include <cmath>
#include <cstddef>
#include <span>
#include <vector>

namespace ocean_test {

struct TransverseWaves {
  double wavelength_m = 0.0;  ///< 2·(span of the crossings)/(crossings − 1); 0 with fewer than 2
  std::size_t crossings = 0;
};

/// Heights h[i] at positions s[i] along the track (s monotonic, any direction): the zero crossings
/// between neighbouring samples, linearly interpolated, within [s_lo, s_hi]; two crossings per
/// wavelength.
inline TransverseWaves transverse_waves(std::span<const double> s, std::span<const double> h,
                                        double s_lo, double s_hi) {
  std::vector<double> zeros;
  for (std::size_t i = 1; i < s.size() && i < h.size(); ++i) {
    const double a = h[i - 1], b = h[i];
    if (s[i] < s_lo || s[i] > s_hi || (a < 0) == (b < 0)) continue;
    zeros.push_back(s[i] + (s[i - 1] - s[i]) * b / (b - a));
  }
  if (zeros.size() < 2) return {.wavelength_m = 0.0, .crossings = zeros.size()};
  return {.wavelength_m =
              2.0 * std::abs(zeros.back() - zeros.front()) / static_cast<double>(zeros.size() - 1),
          .crossings = zeros.size()};
}

}  // namespace ocean_test
