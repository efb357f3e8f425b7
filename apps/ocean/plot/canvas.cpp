// The canvas of the plot module: a cairo RGB24 image surface with rectangles, polylines, discs,
// exact image copies, pixel read-back and PNG output through the io module.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <exception>
#include <numbers>
#include <string>
#include <utility>

#include "cairo_state.hpp"
#include "ocean/io.hpp"
#include "plot_internal.hpp"

namespace ocean::plot {

namespace {

constexpr int kMaxSide = 16384;

void set_color(cairo_t* cr, Rgb c, double opacity = 1.0) {
  cairo_set_source_rgba(cr, c.r / 255.0, c.g / 255.0, c.b / 255.0, opacity);
}

// Liang-Barsky: the parameter range [t0, t1] of a + t (b - a) inside the box; false if none.
bool clip_segment(Point a, Point b, const Box& box, double& t0, double& t1) {
  t0 = 0.0;
  t1 = 1.0;
  const double dx = b.x - a.x, dy = b.y - a.y;
  const double p[4] = {-dx, dx, -dy, dy};
  const double q[4] = {a.x - box.x0, box.x1 - a.x, a.y - box.y0, box.y1 - a.y};
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

bool finite(Point p) { return std::isfinite(p.x) && std::isfinite(p.y); }

}  // namespace

bool detail::segment_meets_box(Point a, Point b, const Box& box) {
  double t0 = 0.0, t1 = 0.0;
  return finite(a) && finite(b) && clip_segment(a, b, box, t0, t1);
}

Canvas::Impl::~Impl() {
  if (cr != nullptr) cairo_destroy(cr);
  if (surface != nullptr) cairo_surface_destroy(surface);
}

Canvas::Canvas(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
Canvas::Canvas(Canvas&&) noexcept = default;
Canvas& Canvas::operator=(Canvas&&) noexcept = default;
Canvas::~Canvas() = default;

Result<Canvas> Canvas::make(int width, int height, Rgb background) {
  if (width < 1 || width > kMaxSide || height < 1 || height > kMaxSide) {
    return invalid_argument("canvas size " + std::to_string(width) + "x" + std::to_string(height) +
                            " is out of range: each side must be in [1, " +
                            std::to_string(kMaxSide) + "]");
  }
  for (const bool bold : {false, true}) {
    if (Result<cairo_font_face_t*> face = detail::font_face(bold); !face.ok()) {
      return face.status();
    }
  }
  auto impl = std::make_unique<Impl>();
  impl->width = width;
  impl->height = height;
  impl->surface = cairo_image_surface_create(CAIRO_FORMAT_RGB24, width, height);
  impl->cr = cairo_create(impl->surface);
  if (cairo_status(impl->cr) != CAIRO_STATUS_SUCCESS) {
    return Status(ErrorCode::internal,
                  "cannot create a " + std::to_string(width) + "x" + std::to_string(height) +
                      " canvas: " + cairo_status_to_string(cairo_status(impl->cr)));
  }
  set_color(impl->cr, background);
  cairo_paint(impl->cr);
  return Canvas(std::move(impl));
}

int Canvas::width() const { return impl_->width; }
int Canvas::height() const { return impl_->height; }

void Canvas::fill(const Box& box, Rgb color, double opacity) {
  cairo_t* cr = impl_->cr;
  set_color(cr, color, std::clamp(opacity, 0.0, 1.0));
  cairo_rectangle(cr, box.x0, box.y0, box.width(), box.height());
  cairo_fill(cr);
}

void Canvas::outline(const Box& box, Rgb color, double width_px) {
  cairo_t* cr = impl_->cr;
  const double h = 0.5 * width_px;
  set_color(cr, color);
  cairo_set_line_width(cr, width_px);
  cairo_set_line_join(cr, CAIRO_LINE_JOIN_MITER);
  cairo_set_dash(cr, nullptr, 0, 0.0);
  cairo_rectangle(cr, box.x0 + h, box.y0 + h, box.width() - width_px, box.height() - width_px);
  cairo_stroke(cr);
}

void Canvas::polyline(std::span<const Point> points, const Stroke& stroke,
                      const std::optional<Box>& clip) {
  const Box canvas{0.0, 0.0, static_cast<double>(impl_->width), static_cast<double>(impl_->height)};
  Box area = clip.value_or(canvas);
  area = {std::max(area.x0, canvas.x0), std::max(area.y0, canvas.y0), std::min(area.x1, canvas.x1),
          std::min(area.y1, canvas.y1)};
  if (!(area.x1 > area.x0) || !(area.y1 > area.y0) || points.size() < 2) return;
  cairo_t* cr = impl_->cr;
  cairo_save(cr);
  cairo_rectangle(cr, area.x0, area.y0, area.width(), area.height());
  cairo_clip(cr);
  // Segments are clipped here to a slightly larger box, so that cairo's fixed-point coordinates
  // never see far-away points, and a line's end caps just outside the area stay cut by the clip.
  const double margin = stroke.width_px + 2.0;
  const Box reach{area.x0 - margin, area.y0 - margin, area.x1 + margin, area.y1 + margin};
  bool open = false;  // whether the current sub-path ends at points[i - 1]
  for (std::size_t i = 1; i < points.size(); ++i) {
    const Point a = points[i - 1], b = points[i];
    double t0 = 0.0, t1 = 0.0;
    if (!finite(a) || !finite(b) || !clip_segment(a, b, reach, t0, t1)) {
      open = false;
      continue;
    }
    const Point p{a.x + t0 * (b.x - a.x), a.y + t0 * (b.y - a.y)};
    const Point q{a.x + t1 * (b.x - a.x), a.y + t1 * (b.y - a.y)};
    if (!open || t0 > 0.0) cairo_move_to(cr, p.x, p.y);
    cairo_line_to(cr, q.x, q.y);
    open = t1 >= 1.0;
  }
  set_color(cr, stroke.color);
  cairo_set_line_width(cr, stroke.width_px);
  cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
  if (stroke.dashed) {
    const double dashes[2] = {3.5 * stroke.width_px, 2.5 * stroke.width_px};
    cairo_set_dash(cr, dashes, 2, 0.0);
    cairo_set_line_cap(cr, CAIRO_LINE_CAP_BUTT);
  } else {
    cairo_set_dash(cr, nullptr, 0, 0.0);
    cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
  }
  cairo_stroke(cr);
  cairo_restore(cr);
}

void Canvas::disc(Point centre, double radius_px, Rgb color) {
  cairo_t* cr = impl_->cr;
  set_color(cr, color);
  cairo_new_path(cr);
  cairo_arc(cr, centre.x, centre.y, radius_px, 0.0, 2.0 * std::numbers::pi);
  cairo_fill(cr);
}

void Canvas::image(int x, int y, const Image& image) {
  if (image.width < 0 || image.height < 0 ||
      image.rgb.size() !=
          static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height) * 3U) {
    return;  // not an image (the contract's precondition)
  }
  cairo_surface_flush(impl_->surface);
  unsigned char* data = cairo_image_surface_get_data(impl_->surface);
  const int stride = cairo_image_surface_get_stride(impl_->surface);
  const int x0 = std::max(x, 0), x1 = std::min(x + image.width, impl_->width);
  const int y0 = std::max(y, 0), y1 = std::min(y + image.height, impl_->height);
  for (int py = y0; py < y1; ++py) {
    auto* row = data + static_cast<std::ptrdiff_t>(py) * stride;
    const std::uint8_t* src = image.rgb.data() + (static_cast<std::size_t>(py - y) *
                                                      static_cast<std::size_t>(image.width) +
                                                  static_cast<std::size_t>(x0 - x)) *
                                                     3U;
    for (int px = x0; px < x1; ++px, src += 3) {
      const std::uint32_t v =
          (std::uint32_t{src[0]} << 16U) | (std::uint32_t{src[1]} << 8U) | std::uint32_t{src[2]};
      std::memcpy(row + static_cast<std::ptrdiff_t>(px) * 4, &v, sizeof v);
    }
  }
  cairo_surface_mark_dirty(impl_->surface);
}

Image Canvas::pixels() const {
  cairo_surface_flush(impl_->surface);
  const unsigned char* data = cairo_image_surface_get_data(impl_->surface);
  const int stride = cairo_image_surface_get_stride(impl_->surface);
  Image out{impl_->width, impl_->height,
            std::vector<std::uint8_t>(static_cast<std::size_t>(impl_->width) *
                                      static_cast<std::size_t>(impl_->height) * 3U)};
  std::uint8_t* dst = out.rgb.data();
  for (int y = 0; y < impl_->height; ++y) {
    const unsigned char* row = data + static_cast<std::ptrdiff_t>(y) * stride;
    for (int x = 0; x < impl_->width; ++x, dst += 3) {
      std::uint32_t v = 0;  // RGB24: one native-endian 32-bit word per pixel, 0x00RRGGBB
      std::memcpy(&v, row + static_cast<std::ptrdiff_t>(x) * 4, sizeof v);
      dst[0] = static_cast<std::uint8_t>(v >> 16U);
      dst[1] = static_cast<std::uint8_t>(v >> 8U);
      dst[2] = static_cast<std::uint8_t>(v);
    }
  }
  return out;
}

Status Canvas::write_png(const std::filesystem::path& path) const {
  try {
    const Image image = pixels();
    return io::write_png8(path, image.width, image.height, 3, image.rgb.data());
  } catch (const std::exception& e) {  // std::bad_alloc
    return io_error("cannot write " + ocean::io::quoted(path) + ": " + e.what());
  }
}

}  // namespace ocean::plot
