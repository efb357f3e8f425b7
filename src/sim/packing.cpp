// The roughness encoding and RGBA8 packing of the surface maps (Aebi, VR Ocean, eqs. 49–53).
#include "packing.hpp"

namespace ocean::packing {

float normal_length_from_roughness(float r) {
  return 1.0f - r * (0.306f + r * (0.113f + r * 0.081f));  // Aebi, VR Ocean, eq. 49
}

float smoothness_from_normal_length(float length) {
  const float t = std::clamp(3.0f * length - 2.0f, 0.0f, 1.0f);  // eq. 53: (|n| − 2/3)/(1/3)
  // r = 1 − t·(0.85 + 0.15·t), factored as (1 − t)(1 + 0.15·t) so that r(1) is exactly 0.
  const float r = (1.0f - t) * (1.0f + 0.15f * t);
  return 1.0f - std::sqrt(r);
}

float normal_length_from_smoothness(float smoothness) {
  const float r = (1.0f - smoothness) * (1.0f - smoothness);
  const float t = (std::sqrt(0.7225f + 0.6f * (1.0f - r)) - 0.85f) / 0.3f;
  return (std::clamp(t, 0.0f, 1.0f) + 2.0f) / 3.0f;
}

std::uint32_t pack_rgba8(float nx, float nz, float blue, float smoothness) {
  const auto quantise = [](float v) {  // ⌊saturate(v)·255 + 0.5⌋   (eq. 50)
    return static_cast<std::uint32_t>(std::clamp(v, 0.0f, 1.0f) * 255.0f + 0.5f);
  };
  return quantise(nx * 0.5f + 0.5f) | (quantise(nz * 0.5f + 0.5f) << 8) | (quantise(blue) << 16) |
         (quantise(smoothness) << 24);  // eq. 51
}

}  // namespace ocean::packing
