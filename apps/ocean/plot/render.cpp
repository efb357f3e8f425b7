// Figure rendering for the plot module: validation, panel layout, grid, ticks, series, legend.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <exception>
#include <string>
#include <vector>

#include "plot_internal.hpp"

namespace ocean::plot {
namespace {

using detail::AxisRange;
using detail::Canvas;
using detail::Point;
using detail::Rect;
using detail::TextDir;

constexpr Rgb kBackground{255, 255, 255};
constexpr Rgb kFrame{0, 0, 0};
constexpr Rgb kText{25, 25, 25};
constexpr Rgb kGrid{220, 220, 220};
constexpr Rgb kMinorGrid{240, 240, 240};
constexpr Rgb kLegendBorder{175, 175, 175};
constexpr int kMinSide = 64, kMaxSide = 16384;
constexpr long long kMaxPixels = 64LL * 1024 * 1024;
constexpr int kMaxGrid = 32;

/// Sizes in pixels derived from the figure size; `s` is the integer text scale (2 at 1600x900).
struct Style {
  double s;
  int cap, pad, gap, tick, minor_tick, frame;
  double title_scale;
};

Style style_for(const Figure& f) {
  const double fit = std::min(f.width_px / 800.0, f.height_px / 450.0);
  const double s = std::clamp(std::round(fit), 1.0, 6.0);
  const auto px = [&](double v) { return static_cast<int>(std::lround(v * s)); };
  return {s,
          px(detail::kCapRows),
          px(6),
          px(3),
          px(3.5),
          px(2),
          std::max(1, px(0.5)),
          std::round(1.5 * s)};
}

/// Maps data values to continuous pixel coordinates (lo -> p0, hi -> p1).
struct Mapper {
  AxisRange r;
  double p0, p1;
  [[nodiscard]] double operator()(double v) const {
    const double t =
        r.log ? (std::log10(v) - std::log10(r.lo)) / (std::log10(r.hi) - std::log10(r.lo))
              : (v - r.lo) / (r.hi - r.lo);
    return p0 + t * (p1 - p0);
  }
};

struct Tick {
  double value;
  std::string label;  // empty for minor ticks
};

struct AxisTicks {
  std::vector<Tick> major, minor;
  int max_label_width = 0;
  int label_rise = 0;  // superscript rise of the labels
};

AxisTicks make_ticks(const AxisRange& r, int max_ticks, double scale) {
  AxisTicks t;
  if (r.log) {
    const detail::LogTicks lt = detail::log_ticks(r.lo, r.hi, max_ticks);
    for (const double v : lt.major) {
      switch (lt.kind) {
        case detail::LogTicks::Kind::decades:
          t.major.push_back({v, detail::format_decade(v)});
          break;
        case detail::LogTicks::Kind::mantissas:
          t.major.push_back({v, detail::compact_number(v)});
          break;
        case detail::LogTicks::Kind::linear:
          t.major.push_back({v, detail::format_linear_tick(v, lt.linear_step)});
          break;
      }
    }
    for (const double v : lt.minor) t.minor.push_back({v, {}});
  } else {
    const double step = detail::nice_step(r.lo, r.hi, max_ticks);
    for (const double v : detail::nice_linear_ticks(r.lo, r.hi, max_ticks)) {
      t.major.push_back({v, detail::format_linear_tick(v, step)});
    }
  }
  for (const Tick& k : t.major) {
    const detail::TextSize ts = detail::measure_text(k.label, scale);
    t.max_label_width = std::max(t.max_label_width, ts.width);
    t.label_rise = std::max(t.label_rise, ts.above);
  }
  return t;
}

/// X ticks: fewer and fewer until neighbouring labels leave a clear gap.
AxisTicks make_x_ticks(const AxisRange& r, int plot_w, const Style& st) {
  int max_ticks = std::clamp(plot_w / (6 * st.cap), 3, 12);
  for (;; --max_ticks) {
    AxisTicks t = make_ticks(r, max_ticks, st.s);
    const Mapper m{r, 0.0, static_cast<double>(plot_w)};
    double min_spacing = 1e300;
    for (std::size_t i = 1; i < t.major.size(); ++i) {
      min_spacing = std::min(min_spacing, m(t.major[i].value) - m(t.major[i - 1].value));
    }
    if (max_ticks <= 2 || min_spacing >= t.max_label_width + 2.5 * st.cap) return t;
  }
}

struct PanelData {
  AxisRange xr, yr;
  std::vector<std::vector<Point>> series;  // data-space points, NaN = gap
};

Result<PanelData> prepare_panel(const Axes& ax, const std::string& name) {
  PanelData pd;
  std::vector<double> xs, ys;
  for (std::size_t k = 0; k < ax.series.size(); ++k) {
    const Series& s = ax.series[k];
    const std::string sname = name + ".series[" + std::to_string(k) + "]" +
                              (s.label.empty() ? "" : " ('" + s.label + "')");
    if (s.x.size() != s.y.size()) {
      return invalid_argument(sname + " has " + std::to_string(s.x.size()) + " x values but " +
                              std::to_string(s.y.size()) + " y values; they must match");
    }
    if (!std::isfinite(s.width_px) || !(s.width_px > 0.0) || s.width_px > 100.0) {
      return invalid_argument(sname + " width_px = " + detail::compact_number(s.width_px) +
                              " is out of range: must be in (0, 100]");
    }
    std::vector<Point> pts;
    pts.reserve(s.x.size());
    for (std::size_t i = 0; i < s.x.size(); ++i) {
      const double x = s.x[i], y = s.y[i];
      const bool ok =
          std::isfinite(x) && std::isfinite(y) && (!ax.log_x || x > 0.0) && (!ax.log_y || y > 0.0);
      if (ok) {
        xs.push_back(x);
        ys.push_back(y);
        pts.push_back({x, y});
      } else {
        pts.push_back({NAN, NAN});
      }
    }
    pd.series.push_back(std::move(pts));
  }
  Result<AxisRange> xr = detail::compute_range(xs, ax.log_x, ax.x_min, ax.x_max, name + ".x");
  if (!xr.ok()) return xr.status();
  Result<AxisRange> yr = detail::compute_range(ys, ax.log_y, ax.y_min, ax.y_max, name + ".y");
  if (!yr.ok()) return yr.status();
  pd.xr = xr.value();
  pd.yr = yr.value();
  return pd;
}

int pixel_of(double p, int lo, int hi) {
  return std::clamp(static_cast<int>(std::floor(p)), lo, hi - 1);
}

void draw_legend(Canvas& cv, const Axes& ax, const Rect& plot, const Style& st) {
  int label_w = 0, n = 0;
  for (const Series& s : ax.series) {
    if (s.label.empty()) continue;
    label_w = std::max(label_w, detail::measure_text(s.label, st.s).width);
    ++n;
  }
  if (n == 0) return;
  const int inner = st.pad * 2 / 3, sample = static_cast<int>(std::lround(22 * st.s));
  const int row_h = st.cap + static_cast<int>(std::lround(6 * st.s));
  const int w = inner * 2 + sample + st.gap * 2 + label_w;
  const int h = inner * 2 + n * row_h - (row_h - st.cap);
  const int x1 = plot.x1 - st.pad, y0 = plot.y0 + st.pad;
  const Rect box{x1 - w, y0, x1, y0 + h};
  cv.fill_rect(box, kBackground, 0.9f);
  cv.fill_rect({box.x0, box.y0, box.x1, box.y0 + 1}, kLegendBorder);
  cv.fill_rect({box.x0, box.y1 - 1, box.x1, box.y1}, kLegendBorder);
  cv.fill_rect({box.x0, box.y0, box.x0 + 1, box.y1}, kLegendBorder);
  cv.fill_rect({box.x1 - 1, box.y0, box.x1, box.y1}, kLegendBorder);
  int y = box.y0 + inner;
  for (const Series& s : ax.series) {
    if (s.label.empty()) continue;
    const double mid = y + st.cap / 2.0;
    const double sx0 = box.x0 + inner + std::min(s.width_px, 8.0) / 2.0;
    const double sx1 = box.x0 + inner + sample - std::min(s.width_px, 8.0) / 2.0;
    detail::stroke_polyline(cv, {{sx0, mid}, {sx1, mid}}, s.color, std::min(s.width_px, 8.0),
                            s.dashed, box);
    detail::draw_text(cv, box.x0 + inner + sample + st.gap * 2, y, s.label, st.s, kText);
    y += row_h;
  }
}

Status draw_panel(Canvas& cv, const Axes& ax, const PanelData& pd, const Rect& cell,
                  const Style& st, const std::string& name) {
  const int descender = static_cast<int>(std::lround(2 * st.s));
  const int rise = static_cast<int>(std::ceil(2.2 * st.s));
  // Vertical layout; the y tick labels overhang the frame by half a cap height at the top.
  int top = cell.y0 + st.pad + st.cap / 2 + (ax.log_y ? rise : 0);
  if (!ax.title.empty()) top = cell.y0 + st.pad + st.cap + st.pad;
  const int bottom = cell.y1 - st.pad - (ax.x_label.empty() ? 0 : st.cap + descender + st.pad) -
                     st.cap - (ax.log_x ? rise : 0) - st.gap - st.tick - st.frame;
  const int plot_h = bottom - top;
  const AxisTicks yt = make_ticks(pd.yr, std::clamp(plot_h / (5 * st.cap), 3, 9), st.s);
  const int left = cell.x0 + st.pad + (ax.y_label.empty() ? 0 : st.cap + descender + st.pad) +
                   yt.max_label_width + st.gap + st.tick + st.frame;
  const int right = cell.x1 - st.pad * 2;
  const Rect plot{left, top, right, bottom};
  if (plot.width() < 4 * st.cap || plot.height() < 4 * st.cap) {
    return invalid_argument(name + " plot area would be only " + std::to_string(plot.width()) +
                            "x" + std::to_string(plot.height()) +
                            " pixels: make the figure larger or use fewer panels");
  }
  const AxisTicks xt = make_x_ticks(pd.xr, plot.width(), st);
  const Mapper xmap{pd.xr, static_cast<double>(plot.x0), static_cast<double>(plot.x1)};
  const Mapper ymap{pd.yr, static_cast<double>(plot.y1), static_cast<double>(plot.y0)};

  // Grid: minor then major, 1 px, crisp.
  for (const auto* ticks : {&xt.minor, &xt.major}) {
    const Rgb c = ticks == &xt.minor ? kMinorGrid : kGrid;
    for (const Tick& t : *ticks) {
      const int x = pixel_of(xmap(t.value), plot.x0, plot.x1);
      cv.fill_rect({x, plot.y0, x + 1, plot.y1}, c);
    }
  }
  for (const auto* ticks : {&yt.minor, &yt.major}) {
    const Rgb c = ticks == &yt.minor ? kMinorGrid : kGrid;
    for (const Tick& t : *ticks) {
      const int y = pixel_of(ymap(t.value), plot.y0, plot.y1);
      cv.fill_rect({plot.x0, y, plot.x1, y + 1}, c);
    }
  }
  // Series, clipped to the plot area.
  for (std::size_t k = 0; k < ax.series.size(); ++k) {
    std::vector<Point> px;
    px.reserve(pd.series[k].size());
    for (const Point& p : pd.series[k]) px.push_back({xmap(p.x), ymap(p.y)});
    const Series& s = ax.series[k];
    detail::stroke_polyline(cv, px, s.color, s.width_px, s.dashed, plot);
  }
  // Frame just outside the plot area.
  const int f = st.frame;
  cv.fill_rect({plot.x0 - f, plot.y0 - f, plot.x1 + f, plot.y0}, kFrame);
  cv.fill_rect({plot.x0 - f, plot.y1, plot.x1 + f, plot.y1 + f}, kFrame);
  cv.fill_rect({plot.x0 - f, plot.y0, plot.x0, plot.y1}, kFrame);
  cv.fill_rect({plot.x1, plot.y0, plot.x1 + f, plot.y1}, kFrame);
  // X ticks and labels.
  const int minor_len = st.minor_tick, major_len = st.tick;
  for (const Tick& t : xt.minor) {
    const int x = pixel_of(xmap(t.value), plot.x0, plot.x1);
    cv.fill_rect({x, plot.y1 + f, x + f, plot.y1 + f + minor_len}, kFrame);
  }
  const int xlabel_top = plot.y1 + f + major_len + st.gap + xt.label_rise;
  for (const Tick& t : xt.major) {
    const int x = pixel_of(xmap(t.value), plot.x0, plot.x1);
    cv.fill_rect({x, plot.y1 + f, x + f, plot.y1 + f + major_len}, kFrame);
    const int w = detail::measure_text(t.label, st.s).width;
    const int lx = std::clamp(x - w / 2, cell.x0, cell.x1 - w);
    detail::draw_text(cv, lx, xlabel_top, t.label, st.s, kText);
  }
  // Y ticks and labels, right-aligned against the ticks.
  for (const Tick& t : yt.minor) {
    const int y = pixel_of(ymap(t.value), plot.y0, plot.y1);
    cv.fill_rect({plot.x0 - f - minor_len, y, plot.x0 - f, y + f}, kFrame);
  }
  for (const Tick& t : yt.major) {
    const int y = pixel_of(ymap(t.value), plot.y0, plot.y1);
    cv.fill_rect({plot.x0 - f - major_len, y, plot.x0 - f, y + f}, kFrame);
    const int w = detail::measure_text(t.label, st.s).width;
    detail::draw_text(cv, plot.x0 - f - major_len - st.gap - w, y - st.cap / 2, t.label, st.s,
                      kText);
  }
  // Axis labels and title.
  if (!ax.x_label.empty()) {
    const int w = detail::measure_text(ax.x_label, st.s).width;
    detail::draw_text(cv, (plot.x0 + plot.x1) / 2 - w / 2, cell.y1 - st.pad - descender - st.cap,
                      ax.x_label, st.s, kText);
  }
  if (!ax.y_label.empty()) {
    const int w = detail::measure_text(ax.y_label, st.s).width;
    detail::draw_text(cv, cell.x0 + st.pad, (plot.y0 + plot.y1) / 2 + w / 2, ax.y_label, st.s,
                      kText, TextDir::up);
  }
  if (!ax.title.empty()) {
    const int w = detail::measure_text(ax.title, st.s).width;
    detail::draw_text(cv, (plot.x0 + plot.x1) / 2 - w / 2, cell.y0 + st.pad, ax.title, st.s, kText,
                      TextDir::horizontal, true);
  }
  draw_legend(cv, ax, plot, st);
  return Status::ok_status();
}

Status validate_figure(const Figure& f) {
  for (const auto& [v, name] :
       {std::pair{f.width_px, "width_px"}, std::pair{f.height_px, "height_px"}}) {
    if (v < kMinSide || v > kMaxSide) {
      return invalid_argument(std::string("figure ") + name + " = " + std::to_string(v) +
                              " is out of range: must be in [" + std::to_string(kMinSide) + ", " +
                              std::to_string(kMaxSide) + "]");
    }
  }
  if (static_cast<long long>(f.width_px) * f.height_px > kMaxPixels) {
    return invalid_argument("figure is " + std::to_string(f.width_px) + "x" +
                            std::to_string(f.height_px) + " pixels: must be at most " +
                            std::to_string(kMaxPixels) + " pixels in all");
  }
  for (const auto& [v, name] : {std::pair{f.rows, "rows"}, std::pair{f.cols, "cols"}}) {
    if (v < 1 || v > kMaxGrid) {
      return invalid_argument(std::string("figure ") + name + " = " + std::to_string(v) +
                              " is out of range: must be in [1, " + std::to_string(kMaxGrid) + "]");
    }
  }
  if (f.panels.size() > static_cast<std::size_t>(f.rows * f.cols)) {
    return invalid_argument("figure has " + std::to_string(f.panels.size()) + " panels but its " +
                            std::to_string(f.rows) + "x" + std::to_string(f.cols) +
                            " grid holds at most " + std::to_string(f.rows * f.cols));
  }
  return Status::ok_status();
}

Result<Image> render_impl(const Figure& figure) {
  if (Status s = validate_figure(figure); !s.ok()) return s;
  std::vector<PanelData> data;
  for (std::size_t i = 0; i < figure.panels.size(); ++i) {
    Result<PanelData> pd = prepare_panel(figure.panels[i], "panels[" + std::to_string(i) + "]");
    if (!pd.ok()) return pd.status();
    data.push_back(std::move(pd).value());
  }
  const Style st = style_for(figure);
  Canvas cv(figure.width_px, figure.height_px, kBackground);
  int grid_top = 0;
  if (!figure.title.empty()) {
    const int cap = static_cast<int>(std::lround(detail::kCapRows * st.title_scale));
    const int w = detail::measure_text(figure.title, st.title_scale).width;
    detail::draw_text(cv, figure.width_px / 2 - w / 2, st.pad + st.pad / 2, figure.title,
                      st.title_scale, kText, TextDir::horizontal, true);
    grid_top = st.pad + st.pad / 2 + cap + st.pad / 2;
  }
  for (std::size_t i = 0; i < figure.panels.size(); ++i) {
    const int row = static_cast<int>(i) / figure.cols, col = static_cast<int>(i) % figure.cols;
    const int gh = figure.height_px - grid_top;
    const Rect cell{col * figure.width_px / figure.cols, grid_top + row * gh / figure.rows,
                    (col + 1) * figure.width_px / figure.cols,
                    grid_top + (row + 1) * gh / figure.rows};
    if (Status s = draw_panel(cv, figure.panels[i], data[i], cell, st,
                              "panels[" + std::to_string(i) + "]");
        !s.ok()) {
      return s;
    }
  }
  return std::move(cv).take();
}

}  // namespace

Result<Image> render(const Figure& figure) {
  try {
    return render_impl(figure);
  } catch (const std::exception& e) {  // std::bad_alloc on a huge figure, mostly
    return Status(ErrorCode::internal, std::string("cannot render figure: ") + e.what());
  }
}

}  // namespace ocean::plot
