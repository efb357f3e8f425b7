// Grid snapping: the ocean square follows the camera in steps that keep every vertex on a fixed
// world lattice, so vertices never swim.
//
// Sources: Aebi, VR Ocean, §5.5 (eq. 69); docs/lod.md L.9.
#include <cmath>

#include "ocean/lod.hpp"

namespace ocean::lod {

// L.9. Level l's vertices sit at centre − S/2 + k·S/(2^l·V). With the centre a multiple of
// S/V and S/2 = (V/2)·(S/V) (V even) every level's lattice is a fixed world lattice. Aebi, VR
// Ocean, eq. 69 prints S/(2V), which moves the level-0 lattice by half its spacing.
double snap_step_m(double ocean_size_m, int vertices) {
  return ocean_size_m / static_cast<double>(vertices);
}

double snap(double value_m, double step_m) { return std::floor(value_m / step_m) * step_m; }

}  // namespace ocean::lod
