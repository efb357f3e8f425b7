// The roles of the bands (docs/math.md M.7.8; Mitchell 2005, §3.3): a frame's cascades made to
// displace only or shade only, after a backend computed them in full.
#include <algorithm>

#include "ocean/sim.hpp"
#include "packing.hpp"

namespace ocean {

namespace {

// A shade-only band keeps its normals, Jacobian and foam but does not move the surface.
void remove_displacement(CascadeFrame& c) {
  std::fill(c.displacement.begin(), c.displacement.end(), 0.0f);
  std::fill(c.displacement_half.begin(), c.displacement_half.end(), std::uint16_t{0});
  std::fill(c.velocity.begin(), c.velocity.end(), 0.0f);  // the time derivative of 0
}

// A displace-only band moves the surface but leaves its shading flat: the normal (0, 1, 0) of
// the base length (eq. 49), J = 1, no foam. Every mip of a flat map is the same texel.
void remove_shading(const SimulationConfig& config, CascadeFrame& c) {
  const float length = packing::normal_length_from_roughness(static_cast<float>(config.roughness));
  const float blue = config.blue_channel == BlueChannel::foam ? 0.0f : 1.0f;  // saturate(J/2 + ½)
  const std::uint32_t flat =
      packing::pack_rgba8(0.0f, 0.0f, blue, packing::smoothness_from_normal_length(length));
  std::fill(c.packed_mips.begin(), c.packed_mips.end(), flat);
  std::fill(c.jacobian.begin(), c.jacobian.end(), 1.0f);
  std::fill(c.foam.begin(), c.foam.end(), 0.0f);
  for (std::size_t i = 0; i + 2 < c.normal.size(); i += 3) {
    c.normal[i] = 0.0f;
    c.normal[i + 1] = 1.0f;
    c.normal[i + 2] = 0.0f;
  }
}

}  // namespace

void apply_band_roles(const SimulationConfig& config, Frame& frame) {
  const std::size_t count = std::min(config.band_roles.size(), frame.cascades.size());
  for (std::size_t c = 0; c < count; ++c) {
    switch (config.band_roles[c]) {
      case BandRole::both: break;
      case BandRole::displace: remove_shading(config, frame.cascades[c]); break;
      case BandRole::shade: remove_displacement(frame.cascades[c]); break;
    }
  }
}

}  // namespace ocean
