// Internal interfaces of the plot module: text markup, legends, ticks and ranges.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "plot.hpp"

namespace ocean::plot::detail {

// ---- text (text.cpp) ----------------------------------------------------------------------------
/// A piece of text split at its superscript markup ('-' after a '^' becomes U+2212 minus).
struct TextRun {
  std::string text;
  bool superscript = false;
};
std::vector<TextRun> parse_markup(std::string_view text);

// ---- canvas (canvas.cpp) ------------------------------------------------------------------------
/// Whether any part of the segment a–b lies inside the box (Liang–Barsky clipping).
bool segment_meets_box(Point a, Point b, const Box& box);

// ---- figures (figure.cpp, legend.cpp) -----------------------------------------------------------
/// Fonts and distances of a figure, in pixels, scaled with the figure's size.
struct Style {
  Font text, title, figure_title;
  double pad = 0.0, gap = 0.0, tick = 0.0, minor_tick = 0.0;
  int frame = 1;  ///< frame and tick line width, whole pixels (crisp)
};

/// Width and height of the panel's legend box; unset when no series has a label.
std::optional<Point> legend_size(const Canvas& canvas, const Axes& axes, const Style& style);
/// The legend's box inside `plot`: the first of the corners and edge midpoints where the box
/// meets none of the curves (pixel coordinates, one polyline per series of `axes`, NaN = gap).
std::optional<Box> legend_inside(Point size, const Box& plot, const Axes& axes,
                                 const std::vector<std::vector<Point>>& curves, const Style& style);
void draw_legend(Canvas& canvas, const Axes& axes, const Box& box, const Style& style);

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
