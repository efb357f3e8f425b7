// Tests for the canvas of the plot module: sizes, exact image copies, lines, text extents and
// the superscript markup, PNG output.
#include <gtest/gtest.h>
#include <png.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

#include "plot.hpp"
#include "plot_internal.hpp"

namespace ocean::plot {
namespace {

namespace fs = std::filesystem;

constexpr Rgb kWhite{255, 255, 255};

Rgb at(const Image& im, int x, int y) {
  const auto i = (static_cast<std::size_t>(y) * static_cast<std::size_t>(im.width) +
                  static_cast<std::size_t>(x)) *
                 3U;
  return {im.rgb[i], im.rgb[i + 1], im.rgb[i + 2]};
}

bool dark(Rgb c) { return c.r < 128 && c.g < 128 && c.b < 128; }

Canvas blank(int w, int h) {
  Result<Canvas> c = Canvas::make(w, h, kWhite);
  EXPECT_TRUE(c.ok()) << c.status().message();
  return std::move(c).value();
}

TEST(PlotCanvas, HasTheRequestedSizeAndBackground) {
  Result<Canvas> c = Canvas::make(123, 45, {10, 200, 30});
  ASSERT_TRUE(c.ok()) << c.status().message();
  const Image im = c.value().pixels();
  EXPECT_EQ(im.width, 123);
  EXPECT_EQ(im.height, 45);
  ASSERT_EQ(im.rgb.size(), 123U * 45U * 3U);
  for (std::size_t i = 0; i < im.rgb.size(); i += 3) {
    ASSERT_EQ(im.rgb[i], 10);
    ASSERT_EQ(im.rgb[i + 1], 200);
    ASSERT_EQ(im.rgb[i + 2], 30);
  }
  for (const auto& [w, h] : {std::pair{0, 10}, std::pair{10, -1}, std::pair{20000, 10}}) {
    Result<Canvas> bad = Canvas::make(w, h, kWhite);
    ASSERT_FALSE(bad.ok());
    EXPECT_EQ(bad.status().code(), ErrorCode::invalid_argument);
  }
}

TEST(PlotCanvas, ImagesAreCopiedExactly) {
  Canvas c = blank(40, 30);
  Image tile{7, 5, {}};
  for (int i = 0; i < 7 * 5 * 3; ++i) tile.rgb.push_back(static_cast<std::uint8_t>(i * 37 % 256));
  c.image(3, 4, tile);
  c.image(36, 27, tile);  // partly outside: clipped
  const Image im = c.pixels();
  for (int y = 0; y < 5; ++y) {
    for (int x = 0; x < 7; ++x) {
      const Rgb want = at(tile, x, y), got = at(im, 3 + x, 4 + y);
      ASSERT_EQ(want.r, got.r);
      ASSERT_EQ(want.g, got.g);
      ASSERT_EQ(want.b, got.b);
    }
  }
  EXPECT_EQ(at(im, 39, 29).r, at(tile, 3, 2).r);
  EXPECT_EQ(at(im, 2, 4).r, 255);  // untouched beside it
}

TEST(PlotCanvas, LinesStayInsideTheirClipAndFarPointsAreFine) {
  Canvas c = blank(100, 100);
  const Point far[] = {{-1e300, 50}, {50, 50}, {1e15, 60}, {NAN, 0}, {10, 10}, {90, 90}};
  c.polyline(far, {.color = {0, 0, 0}, .width_px = 3.0}, Box{20, 20, 80, 80});
  const Image im = c.pixels();
  int inside = 0;
  for (int y = 0; y < 100; ++y) {
    for (int x = 0; x < 100; ++x) {
      const bool in_clip = x >= 20 && x < 80 && y >= 20 && y < 80;
      if (!in_clip) {
        ASSERT_FALSE(dark(at(im, x, y))) << x << "," << y;
      } else {
        inside += dark(at(im, x, y)) ? 1 : 0;
      }
    }
  }
  EXPECT_GT(inside, 100);
}

TEST(PlotCanvas, TextDrawsDarkPixelsInsideItsMeasuredExtent) {
  Canvas c = blank(400, 120);
  const Font font{.size_px = 24.0};
  const std::string text = "Hs = 2.0 m, ω θ ±";
  const TextExtent e = c.measure(text, font);
  EXPECT_GT(e.width, 100.0);
  EXPECT_GT(e.ascent, 0.6 * font.size_px);
  EXPECT_GT(e.descent, 0.0);
  EXPECT_GT(e.cap, 0.5 * font.size_px);
  EXPECT_LT(e.cap, e.ascent);
  const Point origin{20.0, 60.0};
  c.text(origin, text, font, {0, 0, 0});
  const Image im = c.pixels();
  int inside = 0;
  for (int y = 0; y < im.height; ++y) {
    for (int x = 0; x < im.width; ++x) {
      if (!dark(at(im, x, y))) continue;
      // One pixel of slack for antialiasing.
      const bool in = x >= origin.x - 1 && x <= origin.x + e.width + 1 &&
                      y >= origin.y - e.ascent - 1 && y <= origin.y + e.descent + 1;
      ASSERT_TRUE(in) << "dark pixel at " << x << "," << y << " outside the measured extent";
      ++inside;
    }
  }
  EXPECT_GT(inside, 150);
  // Anchored at its end, the same text ends at the anchor point.
  Canvas right = blank(400, 120);
  right.text({380.0, 60.0}, text, font, {0, 0, 0}, Anchor::end);
  const Image r = right.pixels();
  int rightmost = 0;
  for (int y = 0; y < r.height; ++y)
    for (int x = 0; x < r.width; ++x)
      if (dark(at(r, x, y))) rightmost = std::max(rightmost, x);
  EXPECT_LE(rightmost, 381);
  EXPECT_GE(rightmost, 370);
}

TEST(PlotCanvas, UpwardTextRunsBottomToTop) {
  Canvas c = blank(100, 300);
  const Font font{.size_px = 20.0};
  const TextExtent e = c.measure("wavelength, m", font);
  c.text({50.0, 150.0}, "wavelength, m", font, {0, 0, 0}, Anchor::centre, true);
  const Image im = c.pixels();
  int y_min = 300, y_max = 0, x_min = 100, x_max = 0;
  for (int y = 0; y < im.height; ++y) {
    for (int x = 0; x < im.width; ++x) {
      if (!dark(at(im, x, y))) continue;
      y_min = std::min(y_min, y);
      y_max = std::max(y_max, y);
      x_min = std::min(x_min, x);
      x_max = std::max(x_max, x);
    }
  }
  // Tall and narrow, centred on the anchor, glyphs to the left of the baseline.
  EXPECT_NEAR(y_max - y_min, e.width, 4.0);
  EXPECT_NEAR(0.5 * (y_min + y_max), 150.0, 3.0);
  EXPECT_GE(x_min, 50 - e.ascent - 1);
  EXPECT_LE(x_max, 50 + e.descent + 1);
}

TEST(PlotCanvas, SuperscriptMarkup) {
  using detail::parse_markup;
  const auto runs = [](std::string_view s) {
    std::string out;
    for (const detail::TextRun& r : parse_markup(s))
      out += (r.superscript ? "^[" : "[") + r.text + "]";
    return out;
  };
  EXPECT_EQ(runs("10^{-3}"), "[10]^[\u22123]");
  EXPECT_EQ(runs("S, m^2·s/rad"), "[S, m]^[2][·s/rad]");
  EXPECT_EQ(runs("s^-1 x"), "[s]^[\u22121][ x]");
  EXPECT_EQ(runs("a ^ b^"), "[a ^ b^]");  // a '^' without a word after it is literal
  EXPECT_EQ(runs("^{unclosed"), "[^{unclosed]");
  EXPECT_EQ(runs(""), "");
  Canvas c = blank(10, 10);
  const Font font{.size_px = 20.0};
  EXPECT_GT(c.measure("m^2", font).ascent, c.measure("m2", font).ascent);
  EXPECT_LT(c.measure("m^2", font).width, c.measure("m2", font).width);
}

TEST(PlotCanvas, PngRoundTripAndBadPaths) {
  const fs::path dir =
      fs::temp_directory_path() / ("ocean_canvas_test_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  Canvas c = blank(64, 32);
  c.fill({8, 8, 24, 24}, {200, 10, 20});
  c.text({30, 24}, "Ab", {.size_px = 16}, {0, 0, 0});
  const fs::path target = dir / "canvas.png";
  ASSERT_TRUE(c.write_png(target).ok());
  png_image pi{};
  pi.version = PNG_IMAGE_VERSION;
  ASSERT_NE(png_image_begin_read_from_file(&pi, target.c_str()), 0) << pi.message;
  pi.format = PNG_FORMAT_RGB;
  std::vector<std::uint8_t> read(PNG_IMAGE_SIZE(pi));
  ASSERT_NE(png_image_finish_read(&pi, nullptr, read.data(), 0, nullptr), 0) << pi.message;
  EXPECT_EQ(pi.width, 64U);
  EXPECT_EQ(pi.height, 32U);
  EXPECT_EQ(read, c.pixels().rgb);
  const Status missing = c.write_png(dir / "missing" / "x.png");
  EXPECT_EQ(missing.code(), ErrorCode::io_error);
  EXPECT_NE(missing.message().find("cannot write"), std::string::npos) << missing.message();
  EXPECT_EQ(missing.message().find('\n'), std::string::npos);
  EXPECT_FALSE(fs::exists(dir / "missing"));
  fs::remove_all(dir);
}

}  // namespace
}  // namespace ocean::plot
