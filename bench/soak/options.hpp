// The soak program's command line (soak --help prints it).
#pragma once

#include <string>

#include "ocean/core.hpp"

namespace ocean::soak {

struct Options {
  int frames = 10000;  ///< frames simulated and drawn, ≥ 2
  int warmup = -1;     ///< frames before growth is judged, ≥ 1; −1: max(frames / 10, 1)
  std::string backend = "cpu";  ///< the simulation backend: cpu (frames uploaded) or vulkan
  int size = 64;                ///< simulation grid N per cascade (a power of two)
  int width = 128;              ///< render target, pixels
  int height = 72;              ///< render target, pixels
  int windows = 4;              ///< reporting windows after the warm-up, [1, 100]
  bool help = false;            ///< --help: print the usage and exit
};

/// The usage text, one option a line.
const char* usage();

/// Parses argv. invalid_argument with one line naming the flag and the value (excerpted) for an
/// unknown flag, a missing value, a value that is not an integer or out of range (--width and
/// --height as RendererParams, [1, 16384]); the simulation validates --size itself.
Result<Options> parse_options(int argc, char** argv);

}  // namespace ocean::soak
