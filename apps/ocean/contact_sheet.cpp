// Contact sheet of baked maps (see contact_sheet.hpp).
#include "contact_sheet.hpp"

#include <algorithm>
#include <bit>
#include <cmath>

#include "io/png_image.hpp"
#include "plot/plot_internal.hpp"

namespace ocean::cli {

namespace {

using plot::Rgb;
using plot::detail::Canvas;

constexpr int kTile = 300;
constexpr int kMargin = 24;
constexpr int kLabel = 30;
constexpr int kTitle = 50;
constexpr int kColumns = 4;

Rgb lerp(Rgb a, Rgb b, double t) {
  const auto mix = [t](std::uint8_t x, std::uint8_t y) {
    return static_cast<std::uint8_t>(std::lround(x + (y - x) * std::clamp(t, 0.0, 1.0)));
  };
  return {mix(a.r, b.r), mix(a.g, b.g), mix(a.b, b.b)};
}

// Height: deep blue troughs, sea-green mean level, white crests.
Rgb height_color(double t) {
  return t < 0 ? lerp({20, 60, 110}, {8, 20, 50}, -t) : lerp({20, 60, 110}, {235, 245, 250}, t);
}

// Draws tile (col, row) by sampling a texel function over an N×N map (nearest neighbour).
template <typename F>
void draw_tile(Canvas& canvas, int x0, int y0, int n, F&& color_of) {
  for (int y = 0; y < kTile; ++y) {
    for (int x = 0; x < kTile; ++x) {
      const int col = x * n / kTile, row = y * n / kTile;
      canvas.blend(x0 + x, y0 + y, color_of(col, row), 1.0f);
    }
  }
}

}  // namespace

Status write_contact_sheet(const Frame& frame, const std::string& title,
                           const std::filesystem::path& path) {
  const int rows = static_cast<int>(frame.cascades.size());
  const int width = kMargin + kColumns * (kTile + kMargin);
  const int height = kTitle + rows * (kLabel + kTile + kMargin);
  Canvas canvas(width, height, {250, 250, 250});
  const Rgb ink{30, 30, 30};
  plot::detail::draw_text(canvas, kMargin, 14, title, 2.0, ink, plot::detail::TextDir::horizontal,
                          true);
  for (int r = 0; r < rows; ++r) {
    const CascadeFrame& c = frame.cascades[static_cast<std::size_t>(r)];
    const int n = c.resolution;
    const auto at = [n](int col, int row) { return static_cast<std::size_t>(row * n + col); };
    float max_h = 1e-6f;
    for (std::size_t i = 0; i < c.jacobian.size(); ++i)
      max_h = std::max(max_h, std::abs(c.displacement[3 * i + 1]));
    const int y0 = kTitle + r * (kLabel + kTile + kMargin) + kLabel;
    const auto x_of = [](int column) { return kMargin + column * (kTile + kMargin); };
    char label[160];
    std::snprintf(label, sizeof label, "cascade %d: %.0f m  height +-%.2f m", r, c.patch_size_m,
                  double(max_h));
    plot::detail::draw_text(canvas, x_of(0), y0 - 22, label, 1.5, ink);
    plot::detail::draw_text(canvas, x_of(1), y0 - 22, "normal map (x, y, z)", 1.5, ink);
    plot::detail::draw_text(canvas, x_of(2), y0 - 22, "foam (red: J < 0)", 1.5, ink);
    const int level = std::min(3, std::countr_zero(static_cast<unsigned>(n)));
    std::snprintf(label, sizeof label, "smoothness, mip %d", level);
    plot::detail::draw_text(canvas, x_of(3), y0 - 22, label, 1.5, ink);
    draw_tile(canvas, x_of(0), y0, n, [&](int col, int row) {
      return height_color(c.displacement[3 * at(col, row) + 1] / max_h);
    });
    draw_tile(canvas, x_of(1), y0, n, [&](int col, int row) {
      const float* v = &c.normal[3 * at(col, row)];
      const auto channel = [](float x) {
        return static_cast<std::uint8_t>(
            std::lround(std::clamp(x * 0.5f + 0.5f, 0.0f, 1.0f) * 255.0f));
      };
      return Rgb{channel(v[0]), channel(v[2]), channel(v[1])};  // tangent-space style: up is blue
    });
    draw_tile(canvas, x_of(2), y0, n, [&](int col, int row) {
      const std::size_t i = at(col, row);
      const Rgb base = lerp({15, 45, 80}, {250, 250, 250}, c.foam[i]);
      return c.jacobian[i] < 0.0f ? lerp(base, {220, 40, 40}, 0.6) : base;
    });
    const int size = n >> level;
    const std::size_t offset = mip_offset(n, level);
    draw_tile(canvas, x_of(3), y0, size, [&](int col, int row) {
      const std::uint32_t texel =
          c.packed_mips[offset + static_cast<std::size_t>(row * size + col)];
      const auto s = static_cast<std::uint8_t>(texel >> 24);
      return Rgb{s, s, s};
    });
  }
  const plot::Image image = std::move(canvas).take();
  return io::write_png8(path, image.width, image.height, 3, image.rgb.data());
}

}  // namespace ocean::cli
