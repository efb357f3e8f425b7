// Legends of the plot module: the box's size, a place inside the plot area where it covers no
// curve, and the drawing (a line sample and the label per series).
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

#include "plot_internal.hpp"

namespace ocean::plot::detail {

namespace {

constexpr Rgb kText{25, 25, 25};
constexpr Rgb kBackground{255, 255, 255};
constexpr Rgb kBorder{175, 175, 175};

// Distances inside the box, in text ems.
constexpr double kInner = 0.5;     // border to content
constexpr double kSample = 2.2;    // length of a line sample
constexpr double kLabelGap = 0.6;  // sample to label
constexpr double kPitch = 1.35;    // row to row

double sample_width(const Series& s) { return std::min(s.width_px, 8.0); }

int labelled(const Axes& axes) {
  return static_cast<int>(std::count_if(axes.series.begin(), axes.series.end(),
                                        [](const Series& s) { return !s.label.empty(); }));
}

}  // namespace

std::optional<Point> legend_size(const Canvas& canvas, const Axes& axes, const Style& style) {
  const int rows = labelled(axes);
  if (rows == 0) return std::nullopt;
  double label_w = 0.0;
  for (const Series& s : axes.series) {
    if (!s.label.empty()) label_w = std::max(label_w, canvas.measure(s.label, style.text).width);
  }
  const double em = style.text.size_px;
  return Point{std::ceil(em * (2.0 * kInner + kSample + kLabelGap) + label_w),
               std::ceil(em * (2.0 * kInner + kPitch * (rows - 1) + 1.0))};
}

std::optional<Box> legend_inside(Point size, const Box& plot, const Axes& axes,
                                 const std::vector<std::vector<Point>>& curves,
                                 const Style& style) {
  const double inset = std::round(0.6 * style.pad);
  const double left = plot.x0 + inset, right = plot.x1 - inset - size.x;
  const double top = plot.y0 + inset, bottom = plot.y1 - inset - size.y;
  if (right < left || bottom < top) return std::nullopt;
  const double mid_x = std::round(0.5 * (left + right)), mid_y = std::round(0.5 * (top + bottom));
  // Corners first (where legends are looked for), then the middles of the edges.
  const Point corners[] = {{right, top}, {left, top},     {right, bottom}, {left, bottom},
                           {mid_x, top}, {mid_x, bottom}, {right, mid_y},  {left, mid_y}};
  for (const Point& c : corners) {
    const Box box{c.x, c.y, c.x + size.x, c.y + size.y};
    bool clear = true;
    for (std::size_t k = 0; k < curves.size() && clear; ++k) {
      // A curve's stroke reaches half its width from the path, and its antialiasing a pixel more.
      const double reach = 0.5 * axes.series[k].width_px + 1.5;
      const Box near{box.x0 - reach, box.y0 - reach, box.x1 + reach, box.y1 + reach};
      const std::vector<Point>& c_px = curves[k];
      for (std::size_t i = 1; i < c_px.size() && clear; ++i) {
        clear = !segment_meets_box(c_px[i - 1], c_px[i], near);
      }
    }
    if (clear) return box;
  }
  return std::nullopt;
}

void draw_legend(Canvas& canvas, const Axes& axes, const Box& box, const Style& style) {
  canvas.fill(box, kBackground, 0.92);
  canvas.outline(box, kBorder, 1.0);
  const double em = style.text.size_px;
  const double cap = canvas.measure("H", style.text).cap;
  double row_top = box.y0 + kInner * em;
  for (const Series& s : axes.series) {
    if (s.label.empty()) continue;
    const double mid = row_top + 0.5 * em;
    const double w = sample_width(s);
    const double x0 = box.x0 + kInner * em;
    const Point line[] = {{x0 + 0.5 * w, mid}, {x0 + kSample * em - 0.5 * w, mid}};
    canvas.polyline(line, {.color = s.color, .width_px = w, .dashed = s.dashed}, box);
    canvas.text({x0 + (kSample + kLabelGap) * em, mid + 0.5 * cap}, s.label, style.text, kText);
    row_top += kPitch * em;
  }
}

}  // namespace ocean::plot::detail
