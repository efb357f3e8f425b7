// Supersampling's resolve (ocean/render.hpp, docs/rendering.md R.60): block means in linear light.
#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include "ocean/render.hpp"

namespace ocean::render {

namespace {

Status check_blocks(std::size_t size, int width, int height, int factor) {
  if (factor < 1 || width < 1 || height < 1 || width % factor != 0 || height % factor != 0)
    return invalid_argument("supersampling: factor " + std::to_string(factor) +
                            " must be at least 1 and divide the picture's " +
                            std::to_string(width) + " x " + std::to_string(height) + " pixels");
  if (size != static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4)
    return invalid_argument("supersampling: " + std::to_string(size) + " values for a " +
                            std::to_string(width) + " x " + std::to_string(height) +
                            " RGBA picture");
  return {};
}

// Sums each factor × factor block's channels through `decode`, then writes `encode(mean)`.
template <class T, class Decode, class Encode>
std::vector<T> block_means(std::span<const T> rgba, int width, int height, int factor,
                           Decode decode, Encode encode) {
  const int w = width / factor, h = height / factor;
  std::vector<T> out(static_cast<std::size_t>(w) * static_cast<std::size_t>(h) * 4);
  const double inv = 1.0 / (static_cast<double>(factor) * factor);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      std::array<double, 4> sum{};
      for (int dy = 0; dy < factor; ++dy) {
        const std::size_t row =
            static_cast<std::size_t>(y * factor + dy) * static_cast<std::size_t>(width);
        for (int dx = 0; dx < factor; ++dx) {
          const std::size_t i = (row + static_cast<std::size_t>(x * factor + dx)) * 4;
          for (std::size_t c = 0; c < 4; ++c) sum[c] += decode(rgba[i + c], c);
        }
      }
      const std::size_t o = (static_cast<std::size_t>(y) * static_cast<std::size_t>(w) +
                             static_cast<std::size_t>(x)) *
                            4;
      for (std::size_t c = 0; c < 4; ++c) out[o + c] = encode(sum[c] * inv, c);
    }
  }
  return out;
}

}  // namespace

Result<std::vector<std::uint8_t>> resolve_supersampled(std::span<const std::uint8_t> rgba,
                                                       int width, int height, int factor) {
  if (Status s = check_blocks(rgba.size(), width, height, factor); !s.ok()) return s;
  static const std::array<double, 256> kLinear = [] {
    std::array<double, 256> t{};
    for (std::size_t v = 0; v < t.size(); ++v) {
      const double c = static_cast<double>(v) / 255.0;
      t[v] = c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
    }
    return t;
  }();
  const auto decode = [](std::uint8_t v, std::size_t c) {
    return c == 3 ? static_cast<double>(v) : kLinear[v];
  };
  const auto encode = [](double mean, std::size_t c) {
    const double e = c == 3              ? mean
                     : mean <= 0.0031308 ? 12.92 * mean * 255.0
                                         : (1.055 * std::pow(mean, 1.0 / 2.4) - 0.055) * 255.0;
    return static_cast<std::uint8_t>(std::lround(std::clamp(e, 0.0, 255.0)));
  };
  return block_means(rgba, width, height, factor, decode, encode);
}

Result<std::vector<float>> resolve_supersampled(std::span<const float> rgba, int width, int height,
                                                int factor) {
  if (Status s = check_blocks(rgba.size(), width, height, factor); !s.ok()) return s;
  return block_means(
      rgba, width, height, factor, [](float v, std::size_t) { return static_cast<double>(v); },
      [](double mean, std::size_t) { return static_cast<float>(mean); });
}

}  // namespace ocean::render
