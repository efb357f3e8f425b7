// Figures of the plot module: validation, panel layout, grid, ticks, labels, series and titles.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <exception>
#include <string>
#include <utility>
#include <vector>

#include "ocean/io.hpp"
#include "plot_internal.hpp"

namespace ocean::plot {

double Scale::operator()(double v) const {
  const double t = log ? (std::log10(v) - std::log10(lo)) / (std::log10(hi) - std::log10(lo))
                       : (v - lo) / (hi - lo);
  return p0 + t * (p1 - p0);
}

namespace {

using detail::AxisRange;
using detail::Style;

constexpr Rgb kBackground{255, 255, 255};
constexpr Rgb kFrame{0, 0, 0};
constexpr Rgb kText{25, 25, 25};
constexpr Rgb kGrid{220, 220, 220};
constexpr Rgb kMinorGrid{240, 240, 240};
constexpr int kMinSide = 64, kMaxSide = 16384;
constexpr long long kMaxPixels = 64LL * 1024 * 1024;
constexpr int kMaxGrid = 32;

/// Text of 19 px on the 1800×1200 sea-state figure, 17 px at 1600×900, never under 11 px.
Style style_for(const Figure& f) {
  const double fit = std::min(f.width_px / 800.0, f.height_px / 450.0);
  const double em = std::clamp(8.5 * fit, 11.0, 80.0);
  return {.text = {.size_px = em},
          .title = {.size_px = 1.15 * em, .bold = true},
          .figure_title = {.size_px = 1.45 * em, .bold = true},
          .pad = std::round(0.7 * em),
          .gap = std::round(0.35 * em),
          .tick = std::round(0.4 * em),
          .minor_tick = std::round(0.22 * em),
          .frame = std::max(1, static_cast<int>(std::lround(em / 16.0)))};
}

struct Tick {
  double value;
  std::string label;  // empty for minor ticks
};

struct AxisTicks {
  std::vector<Tick> major, minor;
  double max_label_width = 0.0;
  double label_top = 0.0;  // height of the labels' ink above their baseline
};

// A leading '-' of a number is typeset as a minus sign.
std::string typeset(std::string label) {
  if (!label.empty() && label[0] == '-') label.replace(0, 1, "\u2212");
  return label;
}

AxisTicks make_ticks(const Canvas& cv, const AxisRange& r, int max_ticks, const Style& st) {
  AxisTicks t;
  if (r.log) {
    const detail::LogTicks lt = detail::log_ticks(r.lo, r.hi, max_ticks);
    for (const double v : lt.major) {
      switch (lt.kind) {
        case detail::LogTicks::Kind::decades:
          t.major.push_back({v, detail::format_decade(v)});
          break;
        case detail::LogTicks::Kind::mantissas:
          t.major.push_back({v, typeset(detail::compact_number(v))});
          break;
        case detail::LogTicks::Kind::linear:
          t.major.push_back({v, typeset(detail::format_linear_tick(v, lt.linear_step))});
          break;
      }
    }
    for (const double v : lt.minor) t.minor.push_back({v, {}});
  } else {
    const double step = detail::nice_step(r.lo, r.hi, max_ticks);
    for (const double v : detail::nice_linear_ticks(r.lo, r.hi, max_ticks)) {
      t.major.push_back({v, typeset(detail::format_linear_tick(v, step))});
    }
  }
  for (const Tick& k : t.major) {
    const TextExtent e = cv.measure(k.label, st.text);
    t.max_label_width = std::max(t.max_label_width, e.width);
    t.label_top = std::max(t.label_top, k.label.find('^') != std::string::npos ? e.ascent : e.cap);
  }
  return t;
}

/// X ticks: fewer and fewer until neighbouring labels leave a clear gap.
AxisTicks make_x_ticks(const Canvas& cv, const AxisRange& r, double plot_w, const Style& st) {
  const double em = st.text.size_px;
  int max_ticks = std::clamp(static_cast<int>(plot_w / (4.0 * em)), 3, 12);
  for (;; --max_ticks) {
    AxisTicks t = make_ticks(cv, r, max_ticks, st);
    const Scale m{r.lo, r.hi, r.log, 0.0, plot_w};
    double min_spacing = 1e300;
    for (std::size_t i = 1; i < t.major.size(); ++i) {
      min_spacing = std::min(min_spacing, m(t.major[i].value) - m(t.major[i - 1].value));
    }
    if (max_ticks <= 2 || min_spacing >= t.max_label_width + 1.8 * em) return t;
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

/// Everything needed to draw one panel.
struct PanelPlan {
  PanelLayout layout;
  Box cell;
  AxisTicks xt, yt;
};

std::vector<std::vector<Point>> to_pixels(const PanelData& pd, const PanelLayout& l) {
  std::vector<std::vector<Point>> out;
  for (const std::vector<Point>& s : pd.series) {
    std::vector<Point>& px = out.emplace_back();
    px.reserve(s.size());
    for (const Point& p : s) px.push_back({l.x(p.x), l.y(p.y)});
  }
  return out;
}

Result<PanelPlan> plan_panel(const Canvas& cv, const Axes& ax, const PanelData& pd, const Box& cell,
                             const Style& st, const std::string& name) {
  const double em = st.text.size_px;
  const TextExtent line = cv.measure("Hg", st.text);
  const TextExtent title_line = cv.measure("Hg", st.title);
  // Vertical: title, plot area, x tick labels, x label. The y tick labels overhang the frame
  // by half a cap height at the top.
  const double top = std::round(ax.title.empty() ? cell.y0 + st.pad + line.ascent
                                                 : cell.y0 + st.pad + title_line.ascent +
                                                       title_line.descent + st.gap);
  const double x_tick_rise = ax.log_x ? cv.measure("10^{0}", st.text).ascent : line.cap;
  const double bottom =
      std::round(cell.y1 - st.pad - (ax.x_label.empty() ? 0.0 : line.ascent + line.descent) -
                 line.descent - x_tick_rise - st.gap - st.tick - st.frame);
  const double plot_h = bottom - top;
  AxisTicks yt = make_ticks(cv, pd.yr, std::clamp(static_cast<int>(plot_h / (3.6 * em)), 3, 9), st);
  const double left =
      std::round(cell.x0 + st.pad + (ax.y_label.empty() ? 0.0 : line.ascent + line.descent) +
                 yt.max_label_width + st.gap + st.tick + st.frame);
  double right = std::round(cell.x1 - 2.0 * st.pad);
  const auto too_small = [&](double r) { return r - left < 4.0 * em || plot_h < 4.0 * em; };
  if (too_small(right)) {
    return invalid_argument(name + " plot area would be only " +
                            std::to_string(std::lround(std::max(0.0, right - left))) + "x" +
                            std::to_string(std::lround(std::max(0.0, plot_h))) +
                            " pixels: make the figure larger or use fewer panels");
  }
  const auto plan = [&](double r) {
    PanelPlan p;
    p.cell = cell;
    p.layout.plot = {left, top, r, bottom};
    p.layout.x = {pd.xr.lo, pd.xr.hi, pd.xr.log, left, r};
    p.layout.y = {pd.yr.lo, pd.yr.hi, pd.yr.log, bottom, top};
    p.xt = make_x_ticks(cv, pd.xr, r - left, st);
    p.yt = yt;
    return p;
  };
  PanelPlan p = plan(right);
  const std::optional<Point> legend = detail::legend_size(cv, ax, st);
  if (!legend) return p;
  p.layout.legend = detail::legend_inside(*legend, p.layout.plot, ax, to_pixels(pd, p.layout), st);
  if (p.layout.legend) return p;
  // No clear place inside: beside the plot area, which narrows to make room.
  const double narrowed = std::round(cell.x1 - st.pad - legend->x - st.pad - st.frame);
  if (too_small(narrowed)) {  // too narrow a panel: the upper right corner after all
    const double inset = std::round(0.6 * st.pad);
    p.layout.legend =
        Box{right - inset - legend->x, top + inset, right - inset, top + inset + legend->y};
    return p;
  }
  p = plan(narrowed);
  const double x0 = narrowed + st.frame + st.pad;
  p.layout.legend = Box{x0, top, x0 + legend->x, top + legend->y};
  return p;
}

int pixel_of(double p, double lo, double hi) {
  return static_cast<int>(std::clamp(std::floor(p), lo, hi - 1.0));
}

void draw_panel(Canvas& cv, const Axes& ax, const PanelData& pd, const PanelPlan& p,
                const Style& st) {
  const Box& plot = p.layout.plot;
  const Scale& xs = p.layout.x;
  const Scale& ys = p.layout.y;
  const Box& cell = p.cell;
  // Grid: minor then major, 1 px, crisp.
  for (const auto* ticks : {&p.xt.minor, &p.xt.major}) {
    for (const Tick& t : *ticks) {
      const int x = pixel_of(xs(t.value), plot.x0, plot.x1);
      cv.fill({double(x), plot.y0, x + 1.0, plot.y1}, ticks == &p.xt.minor ? kMinorGrid : kGrid);
    }
  }
  for (const auto* ticks : {&p.yt.minor, &p.yt.major}) {
    for (const Tick& t : *ticks) {
      const int y = pixel_of(ys(t.value), plot.y0, plot.y1);
      cv.fill({plot.x0, double(y), plot.x1, y + 1.0}, ticks == &p.yt.minor ? kMinorGrid : kGrid);
    }
  }
  // Series, clipped to the plot area.
  const std::vector<std::vector<Point>> curves = to_pixels(pd, p.layout);
  for (std::size_t k = 0; k < ax.series.size(); ++k) {
    const Series& s = ax.series[k];
    cv.polyline(curves[k], {.color = s.color, .width_px = s.width_px, .dashed = s.dashed}, plot);
  }
  // Frame just outside the plot area.
  const double f = st.frame;
  cv.fill({plot.x0 - f, plot.y0 - f, plot.x1 + f, plot.y0}, kFrame);
  cv.fill({plot.x0 - f, plot.y1, plot.x1 + f, plot.y1 + f}, kFrame);
  cv.fill({plot.x0 - f, plot.y0, plot.x0, plot.y1}, kFrame);
  cv.fill({plot.x1, plot.y0, plot.x1 + f, plot.y1}, kFrame);
  // X ticks and labels.
  const TextExtent line = cv.measure("Hg", st.text);
  for (const Tick& t : p.xt.minor) {
    const int x = pixel_of(xs(t.value), plot.x0, plot.x1);
    cv.fill({double(x), plot.y1 + f, x + f, plot.y1 + f + st.minor_tick}, kFrame);
  }
  const double x_baseline = plot.y1 + f + st.tick + st.gap + p.xt.label_top;
  for (const Tick& t : p.xt.major) {
    const int x = pixel_of(xs(t.value), plot.x0, plot.x1);
    cv.fill({double(x), plot.y1 + f, x + f, plot.y1 + f + st.tick}, kFrame);
    const double w = cv.measure(t.label, st.text).width;
    const double cx = std::clamp(x + 0.5 * f, cell.x0 + 0.5 * w, cell.x1 - 0.5 * w);
    cv.text({cx, x_baseline}, t.label, st.text, kText, Anchor::centre);
  }
  // Y ticks and labels, right-aligned against the ticks and centred on them.
  for (const Tick& t : p.yt.minor) {
    const int y = pixel_of(ys(t.value), plot.y0, plot.y1);
    cv.fill({plot.x0 - f - st.minor_tick, double(y), plot.x0 - f, y + f}, kFrame);
  }
  for (const Tick& t : p.yt.major) {
    const int y = pixel_of(ys(t.value), plot.y0, plot.y1);
    cv.fill({plot.x0 - f - st.tick, double(y), plot.x0 - f, y + f}, kFrame);
    cv.text({plot.x0 - f - st.tick - st.gap, y + 0.5 * f + 0.5 * line.cap}, t.label, st.text, kText,
            Anchor::end);
  }
  // Axis labels and title.
  if (!ax.x_label.empty()) {
    cv.text({0.5 * (plot.x0 + plot.x1), cell.y1 - st.pad - line.descent}, ax.x_label, st.text,
            kText, Anchor::centre);
  }
  if (!ax.y_label.empty()) {
    cv.text({cell.x0 + st.pad + line.ascent, 0.5 * (plot.y0 + plot.y1)}, ax.y_label, st.text, kText,
            Anchor::centre, true);
  }
  if (!ax.title.empty()) {
    cv.text({0.5 * (plot.x0 + plot.x1), cell.y0 + st.pad + cv.measure("Hg", st.title).ascent},
            ax.title, st.title, kText, Anchor::centre);
  }
  if (p.layout.legend) detail::draw_legend(cv, ax, *p.layout.legend, st);
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

struct Plan {
  Style style;
  double title_baseline = 0.0;
  std::vector<PanelData> data;
  std::vector<PanelPlan> panels;
};

/// Validates the figure and lays it out, measuring text on `cv`.
Result<Plan> plan_figure(const Canvas& cv, const Figure& figure) {
  if (Status s = validate_figure(figure); !s.ok()) return s;
  Plan plan;
  plan.style = style_for(figure);
  const Style& st = plan.style;
  for (std::size_t i = 0; i < figure.panels.size(); ++i) {
    Result<PanelData> pd = prepare_panel(figure.panels[i], "panels[" + std::to_string(i) + "]");
    if (!pd.ok()) return pd.status();
    plan.data.push_back(std::move(pd).value());
  }
  double grid_top = 0.0;
  if (!figure.title.empty()) {
    const TextExtent t = cv.measure("Hg", st.figure_title);
    plan.title_baseline = st.pad + t.ascent;
    grid_top = std::round(st.pad + t.ascent + t.descent);
  }
  const double w = figure.width_px, gh = figure.height_px - grid_top;
  for (std::size_t i = 0; i < figure.panels.size(); ++i) {
    const int row = static_cast<int>(i) / figure.cols, col = static_cast<int>(i) % figure.cols;
    const Box cell{std::round(col * w / figure.cols), std::round(grid_top + row * gh / figure.rows),
                   std::round((col + 1) * w / figure.cols),
                   std::round(grid_top + (row + 1) * gh / figure.rows)};
    Result<PanelPlan> p = plan_panel(cv, figure.panels[i], plan.data[i], cell, st,
                                     "panels[" + std::to_string(i) + "]");
    if (!p.ok()) return p.status();
    plan.panels.push_back(std::move(p).value());
  }
  return plan;
}

Result<Image> render_impl(const Figure& figure) {
  if (Status s = validate_figure(figure); !s.ok()) return s;
  Result<Canvas> made = Canvas::make(figure.width_px, figure.height_px, kBackground);
  if (!made.ok()) return made.status();
  Canvas& cv = made.value();
  Result<Plan> plan = plan_figure(cv, figure);
  if (!plan.ok()) return plan.status();
  const Plan& p = plan.value();
  if (!figure.title.empty()) {
    cv.text({0.5 * figure.width_px, p.title_baseline}, figure.title, p.style.figure_title, kText,
            Anchor::centre);
  }
  for (std::size_t i = 0; i < figure.panels.size(); ++i) {
    draw_panel(cv, figure.panels[i], p.data[i], p.panels[i], p.style);
  }
  return cv.pixels();
}

}  // namespace

Result<std::vector<PanelLayout>> layout(const Figure& figure) {
  try {
    Result<Canvas> scratch = Canvas::make(1, 1, kBackground);
    if (!scratch.ok()) return scratch.status();
    Result<Plan> plan = plan_figure(scratch.value(), figure);
    if (!plan.ok()) return plan.status();
    std::vector<PanelLayout> out;
    for (const PanelPlan& p : plan.value().panels) out.push_back(p.layout);
    return out;
  } catch (const std::exception& e) {
    return Status(ErrorCode::internal, std::string("cannot lay out figure: ") + e.what());
  }
}

Result<Image> render(const Figure& figure) {
  try {
    return render_impl(figure);
  } catch (const std::exception& e) {  // std::bad_alloc on a huge figure, mostly
    return Status(ErrorCode::internal, std::string("cannot render figure: ") + e.what());
  }
}

Status write_png(const Figure& figure, const std::filesystem::path& path) {
  Result<Image> image = render(figure);
  if (!image.ok()) return image.status();
  const Image& im = image.value();
  return io::write_png8(path, im.width, im.height, 3, im.rgb.data());
}

}  // namespace ocean::plot
