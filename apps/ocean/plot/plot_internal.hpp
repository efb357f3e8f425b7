// Internal interfaces of the plot module: glyph lookup, the raster canvas, text and tick helpers.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "plot.hpp"

namespace ocean::plot::detail {

// ---- font (font.cpp) ----------------------------------------------------------------------------
/// Glyph cell: 5 columns, 9 rows; rows 0..6 sit above the baseline (cap height 7), rows 7..8 hold
/// descenders. Each row is a 5-bit mask, bit 4 = leftmost column. Advance is 6 columns.
inline constexpr int kGlyphCols = 5;
inline constexpr int kGlyphRows = 9;
inline constexpr int kCapRows = 7;
inline constexpr int kAdvanceCols = 6;
using Glyph = std::array<std::uint8_t, kGlyphRows>;

/// The glyph of a Unicode code point; a boxed '?' for anything not in the font.
const Glyph& glyph_for(char32_t code_point);
/// Decodes UTF-8 leniently: an invalid byte becomes U+FFFD.
std::u32string decode_utf8(std::string_view text);

// ---- canvas (canvas.cpp) ------------------------------------------------------------------------
/// Half-open pixel rectangle [x0, x1) x [y0, y1).
struct Rect {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  [[nodiscard]] int width() const { return x1 - x0; }
  [[nodiscard]] int height() const { return y1 - y0; }
  [[nodiscard]] bool empty() const { return x1 <= x0 || y1 <= y0; }
};
Rect intersect(const Rect& a, const Rect& b);

struct Point {
  double x, y;
};

class Canvas {
 public:
  Canvas(int width, int height, Rgb background);
  [[nodiscard]] int width() const { return width_; }
  [[nodiscard]] int height() const { return height_; }
  [[nodiscard]] Rect bounds() const { return {0, 0, width_, height_}; }
  /// Blends color over the pixel with opacity alpha in [0, 1]; outside pixels are ignored.
  void blend(int x, int y, Rgb color, float alpha);
  void fill_rect(const Rect& r, Rgb color, float alpha = 1.0f);
  [[nodiscard]] Rgb pixel(int x, int y) const;
  Image take() &&;

 private:
  int width_, height_;
  std::vector<std::uint8_t> rgb_;
};

/// A float coverage buffer over a rectangle, composited onto a canvas in one go so that
/// overlapping pieces of one shape (polyline joints, glyph cells) do not double-blend.
class Mask {
 public:
  explicit Mask(const Rect& area);
  /// Adds the exact area of the axis-aligned box [x0,x1] x [y0,y1] to the pixels it overlaps.
  void add_box(double x0, double y0, double x1, double y1);
  /// Max-combines an antialiased round-capped segment of the given width.
  void add_segment(Point a, Point b, double width);
  void composite(Canvas& canvas, Rgb color, float alpha = 1.0f) const;
  [[nodiscard]] const Rect& area() const { return area_; }

 private:
  Rect area_;
  std::vector<float> cov_;
};

/// Strokes a polyline (a NaN point breaks it) clipped to `clip`, solid or dashed.
void stroke_polyline(Canvas& canvas, const std::vector<Point>& points, Rgb color, double width,
                     bool dashed, const Rect& clip);

// ---- text (canvas.cpp) --------------------------------------------------------------------------
enum class TextDir { horizontal, up };  ///< `up`: rotated 90 degrees counter-clockwise
struct TextSize {
  int width = 0;   ///< advance length in pixels
  int above = 0;   ///< pixels a superscript rises above the cap line (0 when none)
  int height = 0;  ///< cap height in pixels (descenders not included)
};
TextSize measure_text(std::string_view text, double scale);
/// Draws text whose cap line starts at (x, y_top) (for `up`: (x, y) is the bottom-left corner
/// of the rotated cap box, text runs upwards). `bold` double-strikes one pixel to the right.
void draw_text(Canvas& canvas, int x, int y_top, std::string_view text, double scale, Rgb color,
               TextDir dir = TextDir::horizontal, bool bold = false);

// ---- axes (axes.cpp) ----------------------------------------------------------------------------
/// 1-2-5 ticks inside [lo, hi], at most max_ticks of them (at least two when the range allows).
std::vector<double> nice_linear_ticks(double lo, double hi, int max_ticks);
/// The step nice_linear_ticks used (needed to format the labels).
double nice_step(double lo, double hi, int max_ticks);

struct LogTicks {
  /// decades: majors are powers of ten (labelled 10^k); mantissas: 1-2-5 (or 1..9) x 10^k;
  /// linear: a range too narrow for either, ticked like a linear axis with `linear_step`.
  enum class Kind { decades, mantissas, linear };
  std::vector<double> major, minor;
  Kind kind = Kind::decades;
  double linear_step = 0.0;
};
/// Decades (every k-th when there are more than max_major) with minor ticks at 2..9 x 10^k; for
/// a range narrower than two decades the majors fall back to 1-2-5 values.
LogTicks log_ticks(double lo, double hi, int max_major);

/// Compact tick labels: "0", "0.5", "1", "2.5e-5", "2e6"; `step` is the tick spacing.
std::string format_linear_tick(double value, double step);
/// A decade label in superscript markup, "10^{-3}".
std::string format_decade(double value);
/// Shortest readable form of a number for labels and messages ("%.6g" with a compact exponent).
std::string compact_number(double value);

struct AxisRange {
  double lo = 0.0, hi = 1.0;
  bool log = false;
};
/// Data range with padding (4 % each side, in log space for log axes), overridden by the
/// explicit limits. `values` must already be filtered (finite, positive on a log axis).
/// `what` names the axis in messages, e.g. "panels[0].x" (limits are then "panels[0].x_min").
ocean::Result<AxisRange> compute_range(const std::vector<double>& values, bool log,
                                       const std::optional<double>& lo,
                                       const std::optional<double>& hi, const std::string& what);

}  // namespace ocean::plot::detail
