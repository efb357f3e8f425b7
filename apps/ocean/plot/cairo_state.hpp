// The cairo side of the plot module's canvas (canvas.cpp, text.cpp): kept out of plot.hpp and
// plot_internal.hpp so that their users need no cairo headers.
#pragma once

#include <cairo.h>

#include "plot.hpp"

/// The cairo state behind a Canvas: an RGB24 image surface and its context.
struct ocean::plot::Canvas::Impl {
  cairo_surface_t* surface = nullptr;
  cairo_t* cr = nullptr;
  int width = 0, height = 0;
  ~Impl();
};

namespace ocean::plot::detail {

/// The DejaVu Sans face (Book or Bold), found once through fontconfig and kept for the life of
/// the process. unsupported when fontconfig has no DejaVu Sans (another family would be
/// substituted silently otherwise).
Result<cairo_font_face_t*> font_face(bool bold);

}  // namespace ocean::plot::detail
