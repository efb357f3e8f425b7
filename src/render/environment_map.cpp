// The HDR environment map's file (docs/rendering.md R.17): an equirectangular OpenEXR image read
// with read_exr (ocean/io.hpp), checked (RGB, twice as wide as high, finite non-negative
// radiance) and halved to at most 2048 × 1024. No device work: the CLI's flag parsers (and their
// fuzz target) use it without the renderer.
#include <cmath>
#include <string>

#include "ocean/io.hpp"
#include "ocean/render.hpp"

namespace ocean::render {

namespace {

constexpr int kMaxWidth = 2048;

// Halves both sides with a 2×2 box (w and h even).
Environment halve(const Environment& e) {
  Environment out{.width = e.width / 2, .height = e.height / 2, .rgb = {}};
  const auto in_w = static_cast<std::size_t>(e.width);
  const auto w = static_cast<std::size_t>(out.width), h = static_cast<std::size_t>(out.height);
  out.rgb.resize(w * h * 3);
  const auto at = [&](std::size_t x, std::size_t y, std::size_t c) {
    return e.rgb[(y * in_w + x) * 3 + c];
  };
  for (std::size_t y = 0; y < h; ++y)
    for (std::size_t x = 0; x < w; ++x)
      for (std::size_t c = 0; c < 3; ++c)
        out.rgb[(y * w + x) * 3 + c] =
            0.25f * (at(2 * x, 2 * y, c) + at(2 * x + 1, 2 * y, c) + at(2 * x, 2 * y + 1, c) +
                     at(2 * x + 1, 2 * y + 1, c));
  return out;
}

}  // namespace

Result<Environment> load_environment(const std::filesystem::path& path) {
  Result<io::ExrImage> read = io::read_exr(path);
  if (!read.ok()) return read.status();
  const io::ExrImage& image = read.value();
  const std::string name = "environment '" + excerpt(path.string()) + "'";
  std::array<const std::vector<float>*, 3> planes{};
  constexpr std::array<const char*, 3> kChannels = {"R", "G", "B"};
  for (std::size_t c = 0; c < 3; ++c) {
    for (std::size_t i = 0; i < image.channel_names.size(); ++i)
      if (image.channel_names[i] == kChannels[c]) planes[c] = &image.planes[i];
    if (planes[c] == nullptr)
      return invalid_argument(name + " has no channel " + kChannels[c] +
                              ": an environment map is an RGB OpenEXR image");
  }
  if (image.width != 2 * image.height || image.height < 2 || image.height % 2 != 0)
    return invalid_argument(name + " is " + std::to_string(image.width) + "x" +
                            std::to_string(image.height) +
                            ": an equirectangular map is twice as wide as high (an even height)");
  Environment e{.width = image.width, .height = image.height, .rgb = {}};
  e.rgb.resize(static_cast<std::size_t>(e.width) * static_cast<std::size_t>(e.height) * 3);
  for (std::size_t p = 0; p < e.rgb.size() / 3; ++p) {
    for (std::size_t c = 0; c < 3; ++c) {
      const float v = (*planes[c])[p];
      if (!std::isfinite(v) || v < 0.0f)
        return invalid_argument(name + " holds a negative or non-finite radiance (" +
                                format_number(v) + "): it must be a linear HDR image");
      e.rgb[3 * p + c] = v;
    }
  }
  while (e.width > kMaxWidth && e.height % 2 == 0) e = halve(e);
  return e;
}

}  // namespace ocean::render
