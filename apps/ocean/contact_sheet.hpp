// Contact sheets: labelled pictures in a grid under a title, as one PNG a person can look at.
// `ocean bake --contact-sheet` shows a frame's maps, `ocean render --contact-sheet` the presets
// from three cameras; both are drawn and written here.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "ocean/sim.hpp"
#include "plot/plot.hpp"

namespace ocean::cli {

struct SheetTile {
  std::string label;  ///< drawn above the picture
  plot::Image image;  ///< copied 1:1, pixel for pixel
};

struct ContactSheet {
  std::string title;             ///< drawn bold at the top ('^' superscript markup, see plot.hpp)
  int columns = 1;               ///< tiles per row, >= 1
  std::vector<SheetTile> tiles;  ///< row-major, all of the first tile's size
};

struct SheetSize {
  int width = 0, height = 0;  ///< pixels
};

/// Draws the sheet and writes it as a PNG, atomically; returns its size. invalid_argument for no
/// tiles, a bad column count or tiles of different sizes; the errors of plot::Canvas (no font) and
/// of io::write_png8 ("cannot write '<path>': <reason>", nothing left behind).
Result<SheetSize> write_contact_sheet(const ContactSheet& sheet, const std::filesystem::path& path);

/// The sheet of a simulated frame: per cascade (one row each), height, normal map, foam and
/// the smoothness a mip level encodes, 300 px square each (nearest texel).
ContactSheet frame_maps_sheet(const Frame& frame, const std::string& title);

}  // namespace ocean::cli
