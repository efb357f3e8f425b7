// ocean/plot — the drawing layer of the tool's figures, on cairo with the DejaVu Sans font.
//
// Two levels, one header:
//  - Canvas: an RGB picture with antialiased lines, rectangles, discs, 1:1 images and text.
//    Used directly by the contact sheets and the LOD diagram.
//  - Figure: line plots in panels, each with axes, ticks, tick labels, axis labels, a title and
//    a legend placed where it covers no curve. Used by the sea-state figure.
//
// Text is UTF-8 drawn with DejaVu Sans (Debian fonts-dejavu-core, found through fontconfig),
// which covers Latin, Greek and the symbols of the figures (° ² · ± × − √ ≈ ≤ ≥ ∞ ...). A '^'
// starts a superscript: "10^{-3}", "m^2·s" or "s^-1" (a '^' followed by a brace group, or by an
// optional sign and an ASCII letter/digit run); any other '^' is literal.
//
// Coordinates are pixels, x to the right, y down, (0, 0) the top-left corner of the top-left
// pixel. Nothing here throws; failures come back as ocean::Status. A Canvas is not thread-safe;
// distinct canvases may be used from different threads.
#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "ocean/core.hpp"

namespace ocean::plot {

struct Rgb {
  std::uint8_t r, g, b;
};

struct Point {
  double x, y;
};

/// The rectangle [x0, x1] × [y0, y1] in pixels.
struct Box {
  double x0 = 0.0, y0 = 0.0, x1 = 0.0, y1 = 0.0;
  [[nodiscard]] double width() const { return x1 - x0; }
  [[nodiscard]] double height() const { return y1 - y0; }
  [[nodiscard]] bool intersects(const Box& o) const {
    return x0 < o.x1 && o.x0 < x1 && y0 < o.y1 && o.y0 < y1;
  }
};

/// An RGB8 image: row-major from the top row, 3 bytes per pixel, no padding.
struct Image {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgb;
};

struct Font {
  double size_px = 14.0;  ///< the em size, in pixels (> 0)
  bool bold = false;
};

/// The size of a piece of text at a font: `width` is the advance from the anchor point,
/// `ascent`/`descent` the line's extent above/below the baseline (superscripts included), `cap`
/// the height of a capital letter (for centring text vertically on a point).
struct TextExtent {
  double width = 0.0, ascent = 0.0, descent = 0.0, cap = 0.0;
};

/// Where the anchor point of a text sits along its reading direction.
enum class Anchor { start, centre, end };

struct Stroke {
  Rgb color{0, 0, 0};
  double width_px = 1.0;  ///< > 0
  bool dashed = false;    ///< dashes 3.5 widths long with gaps of 2.5 widths
};

class Canvas {
 public:
  /// A width×height canvas filled with `background`. invalid_argument unless both sides are in
  /// [1, 16384]; unsupported when the DejaVu Sans font cannot be found (install
  /// fonts-dejavu-core); internal when cairo cannot allocate the surface.
  static Result<Canvas> make(int width, int height, Rgb background);

  Canvas(Canvas&&) noexcept;
  Canvas& operator=(Canvas&&) noexcept;
  ~Canvas();

  [[nodiscard]] int width() const;
  [[nodiscard]] int height() const;

  /// Fills the box, blended over what is there with `opacity` in [0, 1].
  void fill(const Box& box, Rgb color, double opacity = 1.0);
  /// A line of `width_px` along the inside of the box's edge.
  void outline(const Box& box, Rgb color, double width_px);
  /// A polyline through `points`; a non-finite point breaks it. Only what lies inside `clip`
  /// (the whole canvas when unset) is drawn; points far outside (even ±1e300) are fine.
  void polyline(std::span<const Point> points, const Stroke& stroke,
                const std::optional<Box>& clip = std::nullopt);
  void disc(Point centre, double radius_px, Rgb color);
  /// Copies the image's pixels 1:1 with its top-left corner at pixel (x, y), exactly (no
  /// filtering, no blending); parts outside the canvas are left out. An image whose `rgb` does
  /// not hold width*height*3 bytes is not drawn.
  void image(int x, int y, const Image& image);

  /// The extent of `text` (markup applied) at `font`; all zero for an empty text.
  [[nodiscard]] TextExtent measure(std::string_view text, const Font& font) const;
  /// Draws `text` with its baseline through `at`, anchored there by `anchor`. `upward`: rotated
  /// 90° counter-clockwise, reading from bottom to top (a y-axis label).
  void text(Point at, std::string_view text, const Font& font, Rgb color,
            Anchor anchor = Anchor::start, bool upward = false);

  /// The pixels drawn so far.
  [[nodiscard]] Image pixels() const;
  /// Writes the canvas as an 8-bit RGB PNG, atomically (io::write_png8: no half-written file;
  /// io_error "cannot write '<path>': <reason>").
  [[nodiscard]] Status write_png(const std::filesystem::path& path) const;

  struct Impl;

 private:
  explicit Canvas(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

// ---- figures ------------------------------------------------------------------------------------

/// One curve. x and y have the same length; a non-finite point (or a non-positive one on a log
/// axis) breaks the line, leaving a gap.
struct Series {
  std::string label;  ///< legend text; series with an empty label are left out of the legend
  std::vector<double> x, y;
  Rgb color{31, 119, 180};
  double width_px = 2.0;  ///< line width in pixels, (0, 100]
  bool dashed = false;
};

/// One panel: a plot area with its own axes, ticks, labels, title and legend.
struct Axes {
  std::string title, x_label, y_label;
  bool log_x = false, log_y = false;  ///< log axes skip non-positive values
  /// Axis limits; each unset one is taken from the data, with a small padding.
  std::optional<double> x_min, x_max, y_min, y_max;
  std::vector<Series> series;
};

struct Figure {
  int width_px = 1600, height_px = 900;  ///< each in [64, 16384], at most 64 Mpixel in all
  int rows = 1, cols = 1;                ///< panels laid out row-major, each in [1, 32]
  std::string title;                     ///< drawn centred at the top
  std::vector<Axes> panels;              ///< at most rows*cols
};

/// Maps data values of one axis to pixels: lo → p0, hi → p1 (logarithmically on a log axis).
struct Scale {
  double lo = 0.0, hi = 1.0;
  bool log = false;
  double p0 = 0.0, p1 = 1.0;
  [[nodiscard]] double operator()(double value) const;
};

/// Where a panel was drawn: its plot area (the inside of the frame), the axis scales, and the
/// legend's box (unset when no series has a label). The legend lies inside the plot area in the
/// first of the corners and edge midpoints where its box meets no curve, or else to the right of
/// the plot area, which then shrinks to make room (in a panel too narrow for that, in the upper
/// right corner after all).
struct PanelLayout {
  Box plot;
  Scale x, y;
  std::optional<Box> legend;
};

/// The layout render() draws. Same errors as render().
Result<std::vector<PanelLayout>> layout(const Figure& figure);

/// Renders the figure. invalid_argument for bad sizes, mismatched x/y lengths, too many panels,
/// bad axis limits, a log axis with no positive data and no explicit limits, and the like; the
/// errors of Canvas::make.
Result<Image> render(const Figure& figure);

/// render() written as a PNG like Canvas::write_png.
Status write_png(const Figure& figure, const std::filesystem::path& path);

}  // namespace ocean::plot
