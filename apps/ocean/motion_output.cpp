// The motion-vector picture (motion_output.hpp).
#include "motion_output.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "render_output.hpp"

namespace ocean::cli {

Result<double> write_motion_png(const std::filesystem::path& path, int width, int height,
                                const std::vector<float>& xy) {
  const std::size_t n = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
  std::vector<float> length(n);
  for (std::size_t i = 0; i < n; ++i) length[i] = std::hypot(xy[2 * i], xy[2 * i + 1]);
  const std::size_t p99 = n == 0 ? 0 : std::min(n - 1, n * 99 / 100);
  std::nth_element(length.begin(), length.begin() + static_cast<std::ptrdiff_t>(p99), length.end());
  const double scale = std::max(0.01, n == 0 ? 0.0 : static_cast<double>(length[p99]));
  std::vector<std::uint8_t> rgba(4 * n);
  const auto channel = [&](float v) {
    const double c = std::clamp(0.5 + 0.5 * v / scale, 0.0, 1.0);
    return static_cast<std::uint8_t>(std::lround(255.0 * c));
  };
  for (std::size_t i = 0; i < n; ++i) {
    rgba[4 * i] = channel(xy[2 * i]);
    rgba[4 * i + 1] = channel(xy[2 * i + 1]);
    rgba[4 * i + 2] = 128;
    rgba[4 * i + 3] = 255;
  }
  if (Status s = write_srgb_png(path, width, height, rgba); !s.ok()) return s;
  return scale;
}

}  // namespace ocean::cli
