// Raster canvas for the plot module: pixel blending, coverage masks, antialiased strokes, text.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <string_view>
#include <utility>
#include <vector>

#include "plot_internal.hpp"

namespace ocean::plot::detail {

Rect intersect(const Rect& a, const Rect& b) {
  return {std::max(a.x0, b.x0), std::max(a.y0, b.y0), std::min(a.x1, b.x1), std::min(a.y1, b.y1)};
}

// ---- Canvas -------------------------------------------------------------------------------------

Canvas::Canvas(int width, int height, Rgb background)
    : width_(width),
      height_(height),
      rgb_(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 3U) {
  for (std::size_t i = 0; i < rgb_.size(); i += 3) {
    rgb_[i] = background.r;
    rgb_[i + 1] = background.g;
    rgb_[i + 2] = background.b;
  }
}

namespace {
std::uint8_t mix(std::uint8_t under, std::uint8_t over, float alpha) {
  const float v =
      static_cast<float>(under) + (static_cast<float>(over) - static_cast<float>(under)) * alpha;
  return static_cast<std::uint8_t>(std::clamp(std::lround(v), 0L, 255L));
}
}  // namespace

void Canvas::blend(int x, int y, Rgb color, float alpha) {
  if (x < 0 || y < 0 || x >= width_ || y >= height_ || !(alpha > 0.0f)) return;
  alpha = std::min(alpha, 1.0f);
  const std::size_t i = (static_cast<std::size_t>(y) * static_cast<std::size_t>(width_) +
                         static_cast<std::size_t>(x)) *
                        3U;
  rgb_[i] = mix(rgb_[i], color.r, alpha);
  rgb_[i + 1] = mix(rgb_[i + 1], color.g, alpha);
  rgb_[i + 2] = mix(rgb_[i + 2], color.b, alpha);
}

void Canvas::fill_rect(const Rect& r, Rgb color, float alpha) {
  const Rect c = intersect(r, bounds());
  for (int y = c.y0; y < c.y1; ++y) {
    for (int x = c.x0; x < c.x1; ++x) blend(x, y, color, alpha);
  }
}

Rgb Canvas::pixel(int x, int y) const {
  const std::size_t i = (static_cast<std::size_t>(y) * static_cast<std::size_t>(width_) +
                         static_cast<std::size_t>(x)) *
                        3U;
  return {rgb_[i], rgb_[i + 1], rgb_[i + 2]};
}

Image Canvas::take() && { return Image{width_, height_, std::move(rgb_)}; }

// ---- Mask ---------------------------------------------------------------------------------------

Mask::Mask(const Rect& area)
    : area_(area),
      cov_(area.empty()
               ? 0U
               : static_cast<std::size_t>(area.width()) * static_cast<std::size_t>(area.height()),
           0.0f) {}

void Mask::add_box(double x0, double y0, double x1, double y1) {
  if (area_.empty()) return;
  x0 = std::max(x0, static_cast<double>(area_.x0));
  y0 = std::max(y0, static_cast<double>(area_.y0));
  x1 = std::min(x1, static_cast<double>(area_.x1));
  y1 = std::min(y1, static_cast<double>(area_.y1));
  if (!(x1 > x0) || !(y1 > y0)) return;
  const int px0 = static_cast<int>(std::floor(x0)), px1 = static_cast<int>(std::ceil(x1));
  const int py0 = static_cast<int>(std::floor(y0)), py1 = static_cast<int>(std::ceil(y1));
  for (int py = py0; py < py1; ++py) {
    const double oy = std::min(y1, py + 1.0) - std::max(y0, static_cast<double>(py));
    float* row =
        &cov_[static_cast<std::size_t>(py - area_.y0) * static_cast<std::size_t>(area_.width())];
    for (int px = px0; px < px1; ++px) {
      const double ox = std::min(x1, px + 1.0) - std::max(x0, static_cast<double>(px));
      row[px - area_.x0] += static_cast<float>(ox * oy);
    }
  }
}

void Mask::add_segment(Point a, Point b, double width) {
  if (area_.empty()) return;
  const double hw = 0.5 * width;
  const double reach = hw + 1.0;
  const Rect box = intersect(area_, Rect{static_cast<int>(std::floor(std::min(a.x, b.x) - reach)),
                                         static_cast<int>(std::floor(std::min(a.y, b.y) - reach)),
                                         static_cast<int>(std::ceil(std::max(a.x, b.x) + reach)),
                                         static_cast<int>(std::ceil(std::max(a.y, b.y) + reach))});
  const double dx = b.x - a.x, dy = b.y - a.y;
  const double len2 = dx * dx + dy * dy;
  const double outer2 = (hw + 0.5) * (hw + 0.5);
  for (int py = box.y0; py < box.y1; ++py) {
    // Only the columns near the part of the segment that crosses this row's band.
    int x0 = box.x0, x1 = box.x1;
    if (std::fabs(dy) > 1e-9) {
      double ta = (py - reach - a.y) / dy, tb = (py + 1.0 + reach - a.y) / dy;
      if (ta > tb) std::swap(ta, tb);
      ta = std::clamp(ta, 0.0, 1.0);
      tb = std::clamp(tb, 0.0, 1.0);
      const double xa = a.x + ta * dx, xb = a.x + tb * dx;
      x0 = std::max(x0, static_cast<int>(std::floor(std::min(xa, xb) - reach)));
      x1 = std::min(x1, static_cast<int>(std::ceil(std::max(xa, xb) + reach)));
    }
    float* row =
        &cov_[static_cast<std::size_t>(py - area_.y0) * static_cast<std::size_t>(area_.width())];
    for (int px = x0; px < x1; ++px) {
      const double cx = px + 0.5 - a.x, cy = py + 0.5 - a.y;
      const double t = len2 > 0.0 ? std::clamp((cx * dx + cy * dy) / len2, 0.0, 1.0) : 0.0;
      const double ex = cx - t * dx, ey = cy - t * dy;
      const double d2 = ex * ex + ey * ey;
      if (d2 >= outer2) continue;
      const auto c = static_cast<float>(std::clamp(hw + 0.5 - std::sqrt(d2), 0.0, 1.0));
      float& slot = row[px - area_.x0];
      slot = std::max(slot, c);
    }
  }
}

void Mask::composite(Canvas& canvas, Rgb color, float alpha) const {
  for (int y = area_.y0; y < area_.y1; ++y) {
    const float* row =
        &cov_[static_cast<std::size_t>(y - area_.y0) * static_cast<std::size_t>(area_.width())];
    for (int x = area_.x0; x < area_.x1; ++x) {
      const float c = row[x - area_.x0];
      if (c > 0.0f) canvas.blend(x, y, color, std::min(c, 1.0f) * alpha);
    }
  }
}

// ---- strokes ------------------------------------------------------------------------------------

namespace {
// Liang-Barsky: the parameter range [t0, t1] of a + t (b - a) inside the box; false if none.
bool clip_segment(Point a, Point b, double xmin, double ymin, double xmax, double ymax, double& t0,
                  double& t1) {
  t0 = 0.0;
  t1 = 1.0;
  const double dx = b.x - a.x, dy = b.y - a.y;
  const double p[4] = {-dx, dx, -dy, dy};
  const double q[4] = {a.x - xmin, xmax - a.x, a.y - ymin, ymax - a.y};
  for (int i = 0; i < 4; ++i) {
    if (p[i] == 0.0) {
      if (q[i] < 0.0) return false;
      continue;
    }
    const double r = q[i] / p[i];
    if (p[i] < 0.0) {
      t0 = std::max(t0, r);
    } else {
      t1 = std::min(t1, r);
    }
    if (t0 > t1) return false;
  }
  return true;
}
}  // namespace

void stroke_polyline(Canvas& canvas, const std::vector<Point>& points, Rgb color, double width,
                     bool dashed, const Rect& clip) {
  const Rect area = intersect(clip, canvas.bounds());
  if (area.empty() || points.size() < 2) return;
  Mask mask(area);
  const double margin = 0.5 * width + 2.0;
  // Dash geometry along the spine; round caps add width/2 at each end of every dash.
  const double dash_on = std::max(1.0, 5.0 * width + 4.0);
  const double dash_off = 4.0 * width + 4.0;
  const double period = dash_on + dash_off;
  double phase = 0.0;  // arc length since the start of the current unbroken run
  for (std::size_t i = 1; i < points.size(); ++i) {
    const Point a = points[i - 1], b = points[i];
    if (!std::isfinite(a.x) || !std::isfinite(a.y) || !std::isfinite(b.x) || !std::isfinite(b.y)) {
      phase = 0.0;
      continue;
    }
    const double len = std::hypot(b.x - a.x, b.y - a.y);
    double t0 = 0.0, t1 = 0.0;
    const bool visible = clip_segment(a, b, area.x0 - margin, area.y0 - margin, area.x1 + margin,
                                      area.y1 + margin, t0, t1);
    if (visible) {
      const auto at = [&](double s) {
        const double t = len > 0.0 ? s / len : 0.0;
        return Point{a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)};
      };
      const double s0 = t0 * len, s1 = t1 * len;
      if (!dashed) {
        mask.add_segment(at(s0), at(s1), width);
      } else {
        // Dash k covers arc length [k*period, k*period + dash_on) of the run.
        double k = std::floor((phase + s0) / period);
        for (;; k += 1.0) {
          const double on0 = k * period - phase, on1 = on0 + dash_on;
          if (on0 >= s1) break;
          const double u0 = std::max(on0, s0), u1 = std::min(on1, s1);
          if (u1 > u0 || (len == 0.0 && u1 >= u0)) mask.add_segment(at(u0), at(u1), width);
        }
      }
    }
    phase = std::fmod(phase + len, period);
  }
  mask.composite(canvas, color);
}

// ---- text ---------------------------------------------------------------------------------------

namespace {
struct Char {
  char32_t cp;
  bool super;
};

// '^{...}' or '^' + optional sign + alphanumeric run is superscript; any other '^' is literal.
std::vector<Char> parse_markup(std::string_view text) {
  const std::u32string s = decode_utf8(text);
  std::vector<Char> out;
  out.reserve(s.size());
  const auto is_word = [](char32_t c) {
    return (c >= U'0' && c <= U'9') || (c >= U'a' && c <= U'z') || (c >= U'A' && c <= U'Z');
  };
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (s[i] == U'^' && i + 1 < s.size()) {
      if (s[i + 1] == U'{') {
        const std::size_t close = s.find(U'}', i + 2);
        if (close != std::u32string::npos) {
          for (std::size_t k = i + 2; k < close; ++k) out.push_back({s[k], true});
          i = close;
          continue;
        }
      } else {
        std::size_t k = i + 1;
        if (s[k] == U'-' || s[k] == U'+') ++k;
        if (k < s.size() && is_word(s[k])) {
          for (std::size_t m = i + 1; m < k; ++m)
            out.push_back({s[m] == U'-' ? U'\u2212' : s[m], true});
          while (k < s.size() && is_word(s[k])) out.push_back({s[k++], true});
          i = k - 1;
          continue;
        }
      }
    }
    out.push_back({s[i], false});
  }
  return out;
}

constexpr double kSuperScale = 0.7;  // superscript size relative to the base text
constexpr double kSuperRise = 2.2;   // superscript top sits this many base cells above the cap line

double advance_of(const std::vector<Char>& chars, double scale) {
  double w = 0.0;
  for (const Char& c : chars) w += kAdvanceCols * scale * (c.super ? kSuperScale : 1.0);
  if (!chars.empty()) w -= scale * (chars.back().super ? kSuperScale : 1.0);  // no trailing gap
  return w;
}
}  // namespace

TextSize measure_text(std::string_view text, double scale) {
  const std::vector<Char> chars = parse_markup(text);
  const bool any_super =
      std::any_of(chars.begin(), chars.end(), [](const Char& c) { return c.super; });
  return {static_cast<int>(std::ceil(advance_of(chars, scale))),
          any_super ? static_cast<int>(std::ceil(kSuperRise * scale)) : 0,
          static_cast<int>(std::lround(kCapRows * scale))};
}

void draw_text(Canvas& canvas, int x, int y_top, std::string_view text, double scale, Rgb color,
               TextDir dir, bool bold) {
  const std::vector<Char> chars = parse_markup(text);
  if (chars.empty() || !(scale > 0.0)) return;
  const double len = advance_of(chars, scale) + scale + 2.0;
  const double rise = kSuperRise * scale + 1.0, depth = kGlyphRows * scale + 1.0;
  // Text-local coordinates: u along the reading direction, v down from the cap line.
  Rect area;
  if (dir == TextDir::horizontal) {
    area = {x - 1, static_cast<int>(std::floor(y_top - rise)), static_cast<int>(std::ceil(x + len)),
            static_cast<int>(std::ceil(y_top + depth))};
  } else {
    area = {static_cast<int>(std::floor(x - rise)), static_cast<int>(std::floor(y_top - len)),
            static_cast<int>(std::ceil(x + depth)), y_top + 1};
  }
  Mask mask(intersect(area, canvas.bounds()));
  const double bold_shift = bold ? std::max(1.0, std::round(scale / 3.0)) : 0.0;
  const auto add = [&](double u0, double v0, double u1, double v1) {
    if (dir == TextDir::horizontal) {
      mask.add_box(x + u0, y_top + v0, x + u1, y_top + v1);
    } else {
      mask.add_box(x + v0, y_top - u1, x + v1, y_top - u0);
    }
  };
  double pen = 0.0;
  for (const Char& c : chars) {
    const double s = c.super ? scale * kSuperScale : scale;
    const double top = c.super ? -kSuperRise * scale : 0.0;
    const Glyph& gl = glyph_for(c.cp);
    for (int r = 0; r < kGlyphRows; ++r) {
      for (int col = 0; col < kGlyphCols; ++col) {
        if ((gl[static_cast<std::size_t>(r)] >> (kGlyphCols - 1 - col) & 1U) == 0U) continue;
        const double u0 = pen + col * s, v0 = top + r * s;
        add(u0, v0, u0 + s, v0 + s);
        if (bold) add(u0 + bold_shift, v0, u0 + s + bold_shift, v0 + s);
      }
    }
    pen += kAdvanceCols * s;
  }
  mask.composite(canvas, color);
}

}  // namespace ocean::plot::detail
