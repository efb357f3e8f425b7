// Quality presets and the depth of the quadtree.
//
// Sources: Aebi, VR Ocean, §5.1 (Table 2, eq. 56); docs/lod.md L.1.
#include <cmath>
#include <string>

#include "ocean/lod.hpp"

namespace ocean::lod {

std::string_view preset_name(QualityPreset preset) { return name_of(kQualityPresetNames, preset); }

Result<QualityPreset> parse_preset(std::string_view name) {
  if (std::optional<QualityPreset> p = value_of(kQualityPresetNames, name)) return *p;
  return invalid_argument("preset = " + excerpt(name) + " is not a preset: must be " +
                          name_list(kQualityPresetNames, ", ", " or "));
}

// L.1 (Aebi, VR Ocean, eq. 56). The finest nodes are then about 64 m wide whatever S is.
int max_level(double ocean_size_m) {
  const double l = std::floor(std::log2(ocean_size_m / 64.0) + 0.5);
  if (!(l >= 2.0)) return 2;  // also NaN
  if (l > kMaxLevels) return kMaxLevels;
  return static_cast<int>(l);
}

Status validate(const Quality& quality) {
  if (quality.vertices < 2 || quality.vertices > 254 || quality.vertices % 2 != 0) {
    return invalid_argument("quality.vertices = " + std::to_string(quality.vertices) +
                            " is out of range: must be an even integer in [2, 254]");
  }
  if (Status s = require_positive("quality.lod_scale", quality.lod_scale); !s.ok()) return s;
  if (Status s = require_in_range("quality.cull_scale", quality.cull_scale, 1.0, 1e6); !s.ok()) {
    return s;
  }
  return {};
}

}  // namespace ocean::lod
