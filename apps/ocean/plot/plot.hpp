// ocean/plot — a small self-contained PNG line-plot module (figures, panels, series, PNG output).
//
// Text in titles, labels and legends is UTF-8: ASCII, most Greek letters (α β γ δ ε η θ κ λ μ ν π
// ρ σ τ φ ψ ω Γ Δ Θ Λ Σ Φ Ψ Ω) and ° ² ³ · ± × − – — √ ≈ ≤ ≥ ∞; other characters show as a box.
// A '^' starts a superscript: "10^{-3}", "m^2·s" or "s^-1" (a '^' followed by a brace group, or
// by an optional sign and an ASCII letter/digit run). Nothing here throws; failures come back as
// ocean::Status.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "ocean/core.hpp"

namespace ocean::plot {

struct Rgb {
  std::uint8_t r, g, b;
};

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
  int width_px = 1600, height_px = 900;
  int rows = 1, cols = 1;    ///< panels laid out row-major
  std::string title;         ///< drawn centred at the top
  std::vector<Axes> panels;  ///< at most rows*cols
};

/// An RGB8 image: row-major, 3 bytes per pixel, no padding.
struct Image {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgb;
};

/// Renders the figure. invalid_argument for bad sizes, mismatched x/y lengths, too many panels,
/// bad axis limits, a log axis with no positive data and no explicit limits, and the like.
ocean::Result<Image> render(const Figure& figure);

/// Writes a PNG atomically (temporary file in the same directory, fsync, rename over the
/// target). On failure the temporary is removed and an io_error names the path and the reason,
/// e.g. "cannot write 'out/x.png': No such file or directory"; no half-written file is left.
ocean::Status write_png(const Image& image, const std::filesystem::path& path);
/// render() followed by write_png().
ocean::Status write_png(const Figure& figure, const std::filesystem::path& path);

}  // namespace ocean::plot
