// The AArch64 test build reads no height-map file: src/waves/height_map_file.cpp needs libpng for
// arm64, which is a multiarch package (see README.md). This takes its place with the same
// contract's error for every path, so the rest of the waves module (wakes, waveforms from maps
// in memory, the local layer, the damping) and everything above it are built and tested.
#include "ocean/core.hpp"
#include "ocean/waves.hpp"

namespace ocean::waves {

Result<HeightMap> load_height_map(const std::filesystem::path& path) {
  return invalid_argument("cannot read '" + excerpt(path.string()) +
                          "': height-map files are not read in the AArch64 test build");
}

}  // namespace ocean::waves
