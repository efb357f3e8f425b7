// Tests for the figures of the plot module: ticks, labels, rendering, legend placement, input
// validation, PNG output.
#include "plot.hpp"

#include <gtest/gtest.h>
#include <png.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

#include "plot_internal.hpp"

namespace ocean::plot {
namespace {

namespace fs = std::filesystem;

bool same(Rgb a, Rgb b) { return a.r == b.r && a.g == b.g && a.b == b.b; }

Rgb pixel(const Image& im, int x, int y) {
  const auto i = (static_cast<std::size_t>(y) * static_cast<std::size_t>(im.width) +
                  static_cast<std::size_t>(x)) *
                 3U;
  return {im.rgb[i], im.rgb[i + 1], im.rgb[i + 2]};
}

Series line(std::vector<double> x, std::vector<double> y, Rgb color = {31, 119, 180}) {
  Series s;
  s.x = std::move(x);
  s.y = std::move(y);
  s.color = color;
  return s;
}

Figure one_panel(Axes ax, int w = 800, int h = 450) {
  Figure f;
  f.width_px = w;
  f.height_px = h;
  f.panels.push_back(std::move(ax));
  return f;
}

/// A fresh empty directory under the system temp dir, removed at the end of the test.
class TempDir {
 public:
  TempDir() {
    path_ = fs::temp_directory_path() /
            ("ocean_plot_test_" + std::to_string(::getpid()) + "_" + std::to_string(counter_++));
    fs::remove_all(path_);
    fs::create_directories(path_);
  }
  ~TempDir() {
    std::error_code ec;
    fs::remove_all(path_, ec);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  [[nodiscard]] const fs::path& path() const { return path_; }

 private:
  static inline int counter_ = 0;
  fs::path path_;
};

// ---- ticks and labels ---------------------------------------------------------------------------

TEST(PlotTicks, LinearNiceSteps) {
  EXPECT_EQ(detail::nice_linear_ticks(0.0, 9.3, 6), (std::vector<double>{0, 2, 4, 6, 8}));
  EXPECT_EQ(detail::nice_linear_ticks(-1.0, 1.0, 5), (std::vector<double>{-1, -0.5, 0, 0.5, 1}));
  EXPECT_EQ(detail::nice_linear_ticks(0.0, 100.0, 6),
            (std::vector<double>{0, 20, 40, 60, 80, 100}));
  // Rather one tick too many than a single, unreadable one.
  EXPECT_EQ(detail::nice_linear_ticks(3.0, 97.0, 3), (std::vector<double>{20, 40, 60, 80}));
  EXPECT_DOUBLE_EQ(detail::nice_step(0.0, 1.0, 11), 0.1);
  const std::vector<double> small = detail::nice_linear_ticks(0.0012, 0.0049, 5);
  ASSERT_EQ(small.size(), 3U);
  EXPECT_NEAR(small[0], 0.002, 1e-15);
  EXPECT_NEAR(small[1], 0.003, 1e-15);
  EXPECT_NEAR(small[2], 0.004, 1e-15);
  // Every tick set stays within the range and within the budget.
  for (const auto& [lo, hi] :
       {std::pair{-3.7, 12.1}, std::pair{1e6, 3.2e6}, std::pair{0.1, 0.11}}) {
    const std::vector<double> t = detail::nice_linear_ticks(lo, hi, 7);
    EXPECT_GE(t.size(), 2U);
    EXPECT_LE(t.size(), 7U);
    for (const double v : t) {
      EXPECT_GE(v, lo);
      EXPECT_LE(v, hi);
    }
  }
  EXPECT_TRUE(detail::nice_linear_ticks(1.0, 1.0, 5).empty());
  EXPECT_TRUE(detail::nice_linear_ticks(0.0, std::numeric_limits<double>::infinity(), 5).empty());
}

TEST(PlotTicks, LogDecadesWithMinorTicks) {
  const detail::LogTicks t = detail::log_ticks(1e-3, 20.0, 8);
  EXPECT_EQ(t.kind, detail::LogTicks::Kind::decades);
  ASSERT_EQ(t.major.size(), 5U);
  const double expected[] = {1e-3, 1e-2, 1e-1, 1.0, 10.0};
  for (std::size_t i = 0; i < 5; ++i) EXPECT_NEAR(t.major[i], expected[i], expected[i] * 1e-12);
  // 2..9 in each of the four full decades, plus 20.
  ASSERT_EQ(t.minor.size(), 4U * 8U + 1U);
  EXPECT_NEAR(t.minor.front(), 2e-3, 1e-15);
  EXPECT_NEAR(t.minor.back(), 20.0, 1e-12);
}

TEST(PlotTicks, LogManyDecadesThinsMajorsAndNarrowRangeFallsBack) {
  const detail::LogTicks wide = detail::log_ticks(1e-12, 1e12, 7);
  EXPECT_LE(wide.major.size(), 7U);
  EXPECT_GE(wide.major.size(), 4U);
  const detail::LogTicks narrow = detail::log_ticks(2.0, 9.0, 8);
  EXPECT_EQ(narrow.kind, detail::LogTicks::Kind::mantissas);
  EXPECT_GE(narrow.major.size(), 3U);
  for (const double v : narrow.major) {
    EXPECT_GE(v, 2.0);
    EXPECT_LE(v, 9.0);
  }
  const detail::LogTicks tiny = detail::log_ticks(1.5, 1.6, 6);
  EXPECT_EQ(tiny.kind, detail::LogTicks::Kind::linear);
  EXPECT_GE(tiny.major.size(), 2U);
}

TEST(PlotTicks, CompactLabels) {
  EXPECT_EQ(detail::format_linear_tick(0.5, 0.5), "0.5");
  EXPECT_EQ(detail::format_linear_tick(1.0, 0.5), "1");
  EXPECT_EQ(detail::format_linear_tick(2.0, 1.0), "2");
  EXPECT_EQ(detail::format_linear_tick(-0.25, 0.05), "-0.25");
  EXPECT_EQ(detail::format_linear_tick(1e-17, 0.1), "0");
  EXPECT_EQ(detail::format_linear_tick(2e-5, 1e-5), "2e-5");
  EXPECT_EQ(detail::format_linear_tick(2e6, 1e6), "2e6");
  EXPECT_EQ(detail::format_linear_tick(2.5e6, 5e5), "2.5e6");
  EXPECT_EQ(detail::format_linear_tick(1e5, 1e5), "1e5");
  EXPECT_EQ(detail::format_linear_tick(1e6, 1e5), "1e6");
  EXPECT_EQ(detail::format_linear_tick(-3.5e-5, 5e-6), "-3.5e-5");
  EXPECT_EQ(detail::format_linear_tick(40000, 20000), "40000");
  EXPECT_EQ(detail::format_decade(1e-3), "10^{-3}");
  EXPECT_EQ(detail::format_decade(1.0), "10^{0}");
  EXPECT_EQ(detail::compact_number(1.5e-5), "1.5e-5");
  EXPECT_EQ(detail::compact_number(0.25), "0.25");
}

TEST(PlotTicks, RangesArePaddedAndRespectLimits) {
  Result<detail::AxisRange> r = detail::compute_range({0.0, 10.0}, false, {}, {}, "p.x");
  ASSERT_TRUE(r.ok());
  EXPECT_LT(r.value().lo, 0.0);
  EXPECT_GT(r.value().hi, 10.0);
  EXPECT_GT(r.value().lo, -1.0);
  r = detail::compute_range({0.0, 10.0}, false, 2.0, {}, "p.x");
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(r.value().lo, 2.0);
  r = detail::compute_range({1e-3, 1e3}, true, {}, {}, "p.y");
  ASSERT_TRUE(r.ok());
  EXPECT_LT(r.value().lo, 1e-3);
  EXPECT_GT(r.value().lo, 0.0);
  r = detail::compute_range({}, true, {}, {}, "p.y");
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.status().code(), ErrorCode::invalid_argument);
  r = detail::compute_range({}, false, {}, {}, "p.y");  // empty linear axis: a default range
  EXPECT_TRUE(r.ok());
}

// ---- rendering ----------------------------------------------------------------------------------

TEST(PlotRender, BackgroundCornersAndSeriesColour) {
  const Rgb red{200, 30, 40};
  Axes ax;
  ax.title = "panel";
  ax.x_label = "x";
  ax.y_label = "y";
  ax.series.push_back(line({0, 1, 2, 3, 4}, {0, 1, 4, 9, 16}, red));
  Result<Image> im = render(one_panel(ax));
  ASSERT_TRUE(im.ok()) << im.status().message();
  const Image& img = im.value();
  ASSERT_EQ(img.width, 800);
  ASSERT_EQ(img.height, 450);
  ASSERT_EQ(img.rgb.size(), 800U * 450U * 3U);
  const Rgb white{255, 255, 255};
  EXPECT_TRUE(same(pixel(img, 0, 0), white));
  EXPECT_TRUE(same(pixel(img, 799, 0), white));
  EXPECT_TRUE(same(pixel(img, 0, 449), white));
  EXPECT_TRUE(same(pixel(img, 799, 449), white));
  // The curve passes through the middle of the image; look for its exact colour there.
  int hits = 0;
  for (int y = 100; y < 350; ++y) {
    for (int x = 200; x < 600; ++x) hits += same(pixel(img, x, y), red) ? 1 : 0;
  }
  EXPECT_GT(hits, 50);
}

TEST(PlotRender, TickLabelsAreDrawnBesideTheAxes) {
  Axes ax;
  ax.series.push_back(line({0, 1, 2, 3, 4}, {0, 1, 4, 9, 16}));
  const Figure f = one_panel(ax);
  Result<std::vector<PanelLayout>> l = layout(f);
  Result<Image> im = render(f);
  ASSERT_TRUE(l.ok() && im.ok());
  const Box plot = l.value()[0].plot;
  const auto dark_in = [&](int x0, int y0, int x1, int y1) {
    int n = 0;
    for (int y = std::max(y0, 0); y < std::min(y1, im.value().height); ++y) {
      for (int x = std::max(x0, 0); x < std::min(x1, im.value().width); ++x) {
        const Rgb c = pixel(im.value(), x, y);
        n += c.r < 110 && c.g < 110 && c.b < 110 ? 1 : 0;
      }
    }
    return n;
  };
  // Below the frame and its ticks: the x labels; left of them: the y labels.
  const int frame_and_ticks = 12;
  EXPECT_GT(dark_in(static_cast<int>(plot.x0), static_cast<int>(plot.y1) + frame_and_ticks,
                    static_cast<int>(plot.x1), 450),
            30);
  EXPECT_GT(dark_in(0, static_cast<int>(plot.y0), static_cast<int>(plot.x0) - frame_and_ticks,
                    static_cast<int>(plot.y1)),
            30);
  // Nothing dark to the right of the plot area, where no labels belong.
  EXPECT_EQ(dark_in(static_cast<int>(plot.x1) + 2, static_cast<int>(plot.y0) + 2, 800,
                    static_cast<int>(plot.y1) - 2),
            0);
}

TEST(PlotRender, NonFinitePointsLeaveGaps) {
  const Rgb green{20, 160, 40};
  Axes ax;
  ax.x_min = 0.0;
  ax.x_max = 10.0;
  ax.y_min = 0.0;
  ax.y_max = 1.0;
  std::vector<double> x, y;
  for (int i = 0; i <= 100; ++i) {
    x.push_back(i * 0.1);
    y.push_back(i > 40 && i < 60 ? (i % 3 == 0 ? std::numeric_limits<double>::infinity() : NAN)
                                 : 0.5);
  }
  x[3] = -std::numeric_limits<double>::infinity();
  ax.series.push_back(line(x, y, green));
  Result<Image> im = render(one_panel(ax));
  ASSERT_TRUE(im.ok()) << im.status().message();
  // Columns that contain the series colour: two runs with a wide gap between them.
  std::vector<int> cols;
  for (int cx = 0; cx < im.value().width; ++cx) {
    for (int cy = 0; cy < im.value().height; ++cy) {
      if (same(pixel(im.value(), cx, cy), green)) {
        cols.push_back(cx);
        break;
      }
    }
  }
  ASSERT_FALSE(cols.empty());
  int widest_gap = 0, gaps = 0;
  for (std::size_t i = 1; i < cols.size(); ++i) {
    const int g = cols[i] - cols[i - 1];
    if (g > 3) ++gaps;
    widest_gap = std::max(widest_gap, g);
  }
  EXPECT_EQ(gaps, 2);  // around the -inf x at index 3, and the NaN/inf run in the middle
  const int plot_w = cols.back() - cols.front();
  EXPECT_GT(widest_gap, plot_w / 6);
}

TEST(PlotRender, LogAxesSkipNonPositiveValues) {
  Axes ax;
  ax.log_x = ax.log_y = true;
  ax.series.push_back(line({-1, 0, 1e-3, 1e-2, 1, 100}, {1, 1, 1e2, 0, 1e-1, 1e-4}));
  Result<Image> im = render(one_panel(ax));
  EXPECT_TRUE(im.ok()) << im.status().message();
}

TEST(PlotRender, MultiPanelDashedLegendTitlesAndEmptyPanels) {
  Figure f;
  f.rows = 2;
  f.cols = 2;
  f.title = "Figure θ ω m^2";
  Axes a;
  a.title = "log";
  a.log_x = a.log_y = true;
  a.x_label = "ω [rad/s]";
  a.y_label = "S(ω) [m^2 s]";
  Series s = line({0.1, 1, 10}, {1e-3, 1, 1e-5});
  s.label = "curve";
  s.dashed = true;
  s.width_px = 3.5;
  a.series.push_back(s);
  f.panels.push_back(a);
  f.panels.push_back(Axes{});  // no data: default linear range
  Axes c;
  c.series.push_back(line({}, {}));
  f.panels.push_back(c);
  Result<Image> im = render(f);
  ASSERT_TRUE(im.ok()) << im.status().message();
  EXPECT_EQ(im.value().width, 1600);
  EXPECT_EQ(im.value().height, 900);
}

TEST(PlotRender, FarOutOfRangeDataIsClippedQuickly) {
  Axes ax;
  ax.x_min = 0.0;
  ax.x_max = 1.0;
  ax.y_min = 0.0;
  ax.y_max = 1.0;
  ax.series.push_back(line({-1e12, 0.5, 1e15, -1e15}, {-1e12, 0.5, 3e14, 1e300}));
  Result<Image> im = render(one_panel(ax));
  EXPECT_TRUE(im.ok()) << im.status().message();
}

TEST(PlotRender, BadInputsAreInvalidArgument) {
  const auto expect_invalid = [](const Figure& f, const char* what) {
    Result<Image> im = render(f);
    ASSERT_FALSE(im.ok()) << what;
    EXPECT_EQ(im.status().code(), ErrorCode::invalid_argument) << what;
    EXPECT_FALSE(im.status().message().empty()) << what;
  };
  Axes good;
  good.series.push_back(line({0, 1}, {0, 1}));

  Figure f = one_panel(good);
  f.width_px = 0;
  expect_invalid(f, "zero width");
  f = one_panel(good);
  f.height_px = -5;
  expect_invalid(f, "negative height");
  f = one_panel(good);
  f.width_px = 100000;
  expect_invalid(f, "huge width");
  f = one_panel(good);
  f.rows = 0;
  expect_invalid(f, "zero rows");
  f = one_panel(good);
  f.panels.push_back(good);
  expect_invalid(f, "two panels in a 1x1 grid");

  Axes mismatched;
  mismatched.series.push_back(line({0, 1, 2}, {0, 1}));
  expect_invalid(one_panel(mismatched), "mismatched x/y");
  Result<Image> r = render(one_panel(mismatched));
  EXPECT_NE(r.status().message().find("3 x values but 2 y values"), std::string::npos)
      << r.status().message();

  Axes bad_width = good;
  bad_width.series[0].width_px = NAN;
  expect_invalid(one_panel(bad_width), "NaN line width");

  Axes log_empty;
  log_empty.log_y = true;
  log_empty.series.push_back(line({1, 2, 3}, {0, -1, NAN}));
  expect_invalid(one_panel(log_empty), "log axis without positive data");
  Axes log_none;
  log_none.log_x = true;
  expect_invalid(one_panel(log_none), "log axis without any data");

  Axes inverted = good;
  inverted.x_min = 2.0;
  inverted.x_max = 1.0;
  expect_invalid(one_panel(inverted), "x_min > x_max");
  Axes nonfinite_limit = good;
  nonfinite_limit.y_max = std::numeric_limits<double>::infinity();
  expect_invalid(one_panel(nonfinite_limit), "infinite y_max");
  Axes log_negative_limit = good;
  log_negative_limit.log_x = true;
  log_negative_limit.x_min = -1.0;
  expect_invalid(one_panel(log_negative_limit), "negative x_min on log axis");

  Figure crowded;
  crowded.width_px = 200;
  crowded.height_px = 100;
  crowded.rows = 4;
  crowded.cols = 4;
  crowded.panels.assign(16, good);
  expect_invalid(crowded, "panels too small");
}

// ---- legends ------------------------------------------------------------------------------------

/// Whether any segment of any curve of the panel, as drawn, meets the box.
bool legend_meets_a_curve(const Axes& ax, const PanelLayout& l) {
  const Box& b = *l.legend;
  for (const Series& s : ax.series) {
    const double reach = 0.5 * s.width_px;
    const Box near{b.x0 - reach, b.y0 - reach, b.x1 + reach, b.y1 + reach};
    for (std::size_t i = 1; i < s.x.size(); ++i) {
      const Point p{l.x(s.x[i - 1]), l.y(s.y[i - 1])}, q{l.x(s.x[i]), l.y(s.y[i])};
      if (detail::segment_meets_box(p, q, near)) return true;
    }
  }
  return false;
}

Series labelled(std::string label, std::vector<double> x, std::vector<double> y) {
  Series s = line(std::move(x), std::move(y));
  s.label = std::move(label);
  return s;
}

TEST(PlotLegend, AvoidsTheCurvesInsideThePlotArea) {
  // A rising curve fills the upper right and lower left; a falling one the upper left and lower
  // right: the legend must go to the middle of an edge.
  std::vector<double> x, up, down;
  for (int i = 0; i <= 100; ++i) {
    x.push_back(i / 100.0);
    up.push_back(i / 100.0);
    down.push_back(1.0 - i / 100.0);
  }
  Axes ax;
  ax.series.push_back(labelled("rising", x, up));
  ax.series.push_back(labelled("falling", x, down));
  const Figure f = one_panel(ax);
  Result<std::vector<PanelLayout>> l = layout(f);
  ASSERT_TRUE(l.ok()) << l.status().message();
  const PanelLayout& p = l.value()[0];
  ASSERT_TRUE(p.legend.has_value());
  EXPECT_FALSE(legend_meets_a_curve(ax, p));
  // Inside the plot area.
  EXPECT_GE(p.legend->x0, p.plot.x0);
  EXPECT_LE(p.legend->x1, p.plot.x1);
  EXPECT_GE(p.legend->y0, p.plot.y0);
  EXPECT_LE(p.legend->y1, p.plot.y1);
}

TEST(PlotLegend, GoesBesideThePlotWhenEveryPlaceInsideIsTaken) {
  // A zigzag over the whole plot area leaves no clear place inside.
  std::vector<double> x, y;
  for (int i = 0; i <= 400; ++i) {
    x.push_back(i);
    y.push_back(i % 2);
  }
  Axes ax;
  ax.series.push_back(labelled("zigzag", x, y));
  Result<std::vector<PanelLayout>> l = layout(one_panel(ax));
  ASSERT_TRUE(l.ok()) << l.status().message();
  const PanelLayout& p = l.value()[0];
  ASSERT_TRUE(p.legend.has_value());
  EXPECT_GT(p.legend->x0, p.plot.x1);
  EXPECT_LE(p.legend->x1, 800.0);
  EXPECT_FALSE(legend_meets_a_curve(ax, p));
  // No labels, no legend.
  ax.series[0].label.clear();
  l = layout(one_panel(ax));
  ASSERT_TRUE(l.ok());
  EXPECT_FALSE(l.value()[0].legend.has_value());
}

TEST(PlotLegend, IsDrawnWithItsLabels) {
  Axes ax;
  ax.series.push_back(labelled("first", {0, 1}, {0, 0.1}));
  const Figure f = one_panel(ax);
  Result<std::vector<PanelLayout>> l = layout(f);
  ASSERT_TRUE(l.ok());
  Result<Image> im = render(f);
  ASSERT_TRUE(im.ok());
  const Box b = *l.value()[0].legend;
  // Text inside the box: dark pixels.
  int dark = 0;
  for (int y = static_cast<int>(b.y0) + 1; y < static_cast<int>(b.y1) - 1; ++y) {
    for (int x = static_cast<int>(b.x0) + 1; x < static_cast<int>(b.x1) - 1; ++x) {
      const Rgb c = pixel(im.value(), x, y);
      dark += c.r < 100 && c.g < 100 && c.b < 100 ? 1 : 0;
    }
  }
  EXPECT_GT(dark, 20);
}

// ---- PNG output ---------------------------------------------------------------------------------

TEST(PlotPng, MissingDirectoryIsAOneLineIoErrorAndLeavesNothing) {
  TempDir dir;
  const fs::path target = dir.path() / "no_such_dir" / "x.png";
  Axes ax;
  ax.series.push_back(line({0, 1}, {0, 1}));
  const Status s = write_png(one_panel(ax), target);
  ASSERT_FALSE(s.ok());
  EXPECT_EQ(s.code(), ErrorCode::io_error);
  EXPECT_NE(s.message().find("cannot write '" + target.string() + "'"), std::string::npos)
      << s.message();
  EXPECT_NE(s.message().find("No such file or directory"), std::string::npos) << s.message();
  EXPECT_EQ(s.message().find('\n'), std::string::npos) << s.message();
  EXPECT_FALSE(fs::exists(target));
  EXPECT_FALSE(fs::exists(target.parent_path()));
  EXPECT_TRUE(fs::is_empty(dir.path()));
}

TEST(PlotPng, WrittenFileReadsBackWithLibpng) {
  TempDir dir;
  const fs::path target = dir.path() / "figure.png";
  Axes ax;
  ax.title = "readback";
  ax.series.push_back(line({0, 1, 2}, {2, 0, 1}, {10, 20, 250}));
  const Figure f = one_panel(ax, 640, 360);
  Result<Image> im = render(f);
  ASSERT_TRUE(im.ok()) << im.status().message();
  // Written twice: the second write replaces the first atomically.
  ASSERT_TRUE(write_png(f, target).ok());
  const Status s = write_png(f, target);
  ASSERT_TRUE(s.ok()) << s.message();

  png_image pi{};
  pi.version = PNG_IMAGE_VERSION;
  ASSERT_NE(png_image_begin_read_from_file(&pi, target.c_str()), 0) << pi.message;
  EXPECT_EQ(pi.width, 640U);
  EXPECT_EQ(pi.height, 360U);
  pi.format = PNG_FORMAT_RGB;
  std::vector<std::uint8_t> pixels(PNG_IMAGE_SIZE(pi));
  ASSERT_NE(png_image_finish_read(&pi, nullptr, pixels.data(), 0, nullptr), 0) << pi.message;
  EXPECT_EQ(pixels, im.value().rgb);

  // Only the target is left in the directory: no temporaries.
  int entries = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir.path())) ++entries;
  EXPECT_EQ(entries, 1);
}

TEST(PlotPng, RejectsBadPathsAndFigures) {
  TempDir dir;
  Axes ax;
  ax.series.push_back(line({0, 1}, {0, 1}));
  Status s = write_png(one_panel(ax), dir.path() / "");
  EXPECT_EQ(s.code(), ErrorCode::invalid_argument);
  s = write_png(one_panel(ax), dir.path());  // a directory
  EXPECT_EQ(s.code(), ErrorCode::io_error) << s.message();
  EXPECT_TRUE(fs::is_directory(dir.path()));
  EXPECT_TRUE(fs::is_empty(dir.path()));
  // An invalid figure is reported as such and writes nothing.
  Figure f;
  f.width_px = 1;
  s = write_png(f, dir.path() / "f.png");
  EXPECT_EQ(s.code(), ErrorCode::invalid_argument);
  EXPECT_TRUE(fs::is_empty(dir.path()));
}

}  // namespace
}  // namespace ocean::plot
