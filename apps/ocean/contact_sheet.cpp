// Contact sheets (see contact_sheet.hpp): the grid of labelled tiles, and the tiles of a frame's
// maps.
#include "contact_sheet.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdio>
#include <utility>

namespace ocean::cli {

namespace {

using plot::Rgb;

constexpr Rgb kPaper{250, 250, 250};
constexpr Rgb kSheetInk{30, 30, 30};
constexpr plot::Font kLabelFont{.size_px = 15.0};
constexpr plot::Font kTitleFont{.size_px = 21.0, .bold = true};
constexpr int kMargin = 16;  // around and between tiles
constexpr int kLabel = 26;   // band above each tile for its label
constexpr int kTitle = 54;   // band at the top for the title
constexpr int kMapTile = 300;

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

// A kMapTile-square picture of an N×N map, sampled at the nearest texel.
template <typename F>
plot::Image map_tile(int n, F&& color_of) {
  plot::Image image{kMapTile, kMapTile, std::vector<std::uint8_t>(kMapTile * kMapTile * 3)};
  std::uint8_t* p = image.rgb.data();
  for (int y = 0; y < kMapTile; ++y) {
    for (int x = 0; x < kMapTile; ++x, p += 3) {
      const Rgb c = color_of(x * n / kMapTile, y * n / kMapTile);
      p[0] = c.r;
      p[1] = c.g;
      p[2] = c.b;
    }
  }
  return image;
}

}  // namespace

Result<SheetSize> write_contact_sheet(const ContactSheet& sheet,
                                      const std::filesystem::path& path) {
  if (sheet.tiles.empty() || sheet.columns < 1) {
    return invalid_argument("contact sheet needs tiles and at least one column");
  }
  const int tw = sheet.tiles.front().image.width, th = sheet.tiles.front().image.height;
  for (const SheetTile& t : sheet.tiles) {
    if (t.image.width != tw || t.image.height != th) {
      return invalid_argument("contact sheet tiles differ in size");
    }
  }
  const int cols = std::min(sheet.columns, static_cast<int>(sheet.tiles.size()));
  const int rows = (static_cast<int>(sheet.tiles.size()) + cols - 1) / cols;
  const SheetSize size{kMargin + cols * (tw + kMargin), kTitle + rows * (kLabel + th + kMargin)};
  Result<plot::Canvas> made = plot::Canvas::make(size.width, size.height, kPaper);
  if (!made.ok()) return made.status();
  plot::Canvas& canvas = made.value();
  canvas.text({kMargin, kTitle - 0.6 * kMargin}, sheet.title, kTitleFont, kSheetInk);
  for (std::size_t i = 0; i < sheet.tiles.size(); ++i) {
    const int r = static_cast<int>(i) / cols, c = static_cast<int>(i) % cols;
    const int x0 = kMargin + c * (tw + kMargin);
    const int y0 = kTitle + r * (kLabel + th + kMargin) + kLabel;
    canvas.text({static_cast<double>(x0), y0 - 0.45 * kLabel}, sheet.tiles[i].label, kLabelFont,
                kSheetInk);
    canvas.image(x0, y0, sheet.tiles[i].image);
  }
  if (Status s = canvas.write_png(path); !s.ok()) return s;
  return size;
}

ContactSheet frame_maps_sheet(const Frame& frame, const std::string& title) {
  ContactSheet sheet{.title = title, .columns = 4};
  for (std::size_t r = 0; r < frame.cascades.size(); ++r) {
    const CascadeFrame& c = frame.cascades[r];
    const int n = c.resolution;
    const auto at = [n](int col, int row) { return static_cast<std::size_t>(row * n + col); };
    float max_h = 1e-6f;
    for (std::size_t i = 0; i < c.jacobian.size(); ++i)
      max_h = std::max(max_h, std::abs(c.displacement[3 * i + 1]));
    char label[160];
    std::snprintf(label, sizeof label, "cascade %zu: %.0f m, height ±%.2f m", r, c.patch_size_m,
                  double(max_h));
    sheet.tiles.push_back({label, map_tile(n, [&](int col, int row) {
                             return height_color(c.displacement[3 * at(col, row) + 1] / max_h);
                           })});
    sheet.tiles.push_back({"normal map (x, y, z)", map_tile(n, [&](int col, int row) {
                             const float* v = &c.normal[3 * at(col, row)];
                             const auto channel = [](float x) {
                               return static_cast<std::uint8_t>(
                                   std::lround(std::clamp(x * 0.5f + 0.5f, 0.0f, 1.0f) * 255.0f));
                             };
                             // Tangent-space style: up is blue.
                             return Rgb{channel(v[0]), channel(v[2]), channel(v[1])};
                           })});
    sheet.tiles.push_back({"foam (red: J < 0)", map_tile(n, [&](int col, int row) {
                             const std::size_t i = at(col, row);
                             const Rgb base = lerp({15, 45, 80}, {250, 250, 250}, c.foam[i]);
                             return c.jacobian[i] < 0.0f ? lerp(base, {220, 40, 40}, 0.6) : base;
                           })});
    const int level = std::min(3, std::countr_zero(static_cast<unsigned>(n)));
    const int size = n >> level;
    const std::size_t offset = mip_offset(n, level);
    std::snprintf(label, sizeof label, "smoothness, mip %d", level);
    sheet.tiles.push_back({label, map_tile(size, [&](int col, int row) {
                             const std::uint32_t texel =
                                 c.packed_mips[offset + static_cast<std::size_t>(row * size + col)];
                             const auto s = static_cast<std::uint8_t>(texel >> 24);
                             return Rgb{s, s, s};
                           })});
  }
  return sheet;
}

}  // namespace ocean::cli
