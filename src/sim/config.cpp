// Simulation configuration: validation, cascade wavenumber bands and the mip-chain layout.
//
// Sources: Vincevičius 2024, §2.5 (cascades against tiling); Aebi, VR Ocean, eq. 55 (mip
// offsets).
// Equations: docs/math.md §7.
#include <bit>
#include <cmath>
#include <string>

#include "ocean/sim.hpp"

namespace ocean {

std::string_view to_string(NormalMethod method) { return name_of(kNormalMethodNames, method); }

Result<NormalMethod> parse_normal_method(std::string_view name) {
  if (std::optional<NormalMethod> m = value_of(kNormalMethodNames, name)) return *m;
  return invalid_argument("normals = '" + std::string(name) + "' is unknown: must be one of " +
                          name_list(kNormalMethodNames, ", ", ", "));
}

Status validate(const SimulationConfig& c) {
  const int n = c.resolution;
  if (n < 16 || n > 2048 || !std::has_single_bit(static_cast<unsigned>(n))) {
    return invalid_argument("resolution = " + std::to_string(n) +
                            " is out of range: must be a power of two in [16, 2048]");
  }
  if (c.cascade_patch_sizes_m.empty() || c.cascade_patch_sizes_m.size() > 8) {
    return invalid_argument("cascades = " + std::to_string(c.cascade_patch_sizes_m.size()) +
                            " is out of range: must be 1 to 8 patch sizes");
  }
  for (std::size_t i = 0; i < c.cascade_patch_sizes_m.size(); ++i) {
    const double size = c.cascade_patch_sizes_m[i];
    const std::string name = "patch_size_m[" + std::to_string(i) + "]";
    if (Status s = require_in_range(name, size, 0.01, 1e6); !s.ok()) return s;
    if (i > 0 && !(size < c.cascade_patch_sizes_m[i - 1])) {
      return invalid_argument(
          name + " = " + format_number(size) + " must be smaller than the previous cascade's " +
          format_number(c.cascade_patch_sizes_m[i - 1]) + " (largest patch first)");
    }
  }
  if (Status s = require_in_range("choppiness", c.choppiness, 0.0, 10.0); !s.ok()) return s;
  if (Status s = require_in_range("loop_period_s", c.loop_period_s, 0.0, 1e6); !s.ok()) return s;
  if (Status s = require_in_range("roughness", c.roughness, 0.0, 1.0); !s.ok()) return s;
  if (Status s = require_in_range("foam.jacobian_start", c.foam.jacobian_start, -10.0, 10.0);
      !s.ok()) {
    return s;
  }
  if (!(c.foam.jacobian_full < c.foam.jacobian_start) || !std::isfinite(c.foam.jacobian_full)) {
    return invalid_argument("foam.jacobian_full = " + format_number(c.foam.jacobian_full) +
                            " is out of range: must be finite and below foam.jacobian_start = " +
                            format_number(c.foam.jacobian_start));
  }
  return require_in_range("foam.decay_per_s", c.foam.decay_per_s, 0.0, 1e6);
}

std::vector<std::array<double, 2>> cascade_bands(const SimulationConfig& c) {
  std::vector<std::array<double, 2>> bands;
  const double n = static_cast<double>(c.resolution);
  double k_min = 0.0;
  for (std::size_t i = 0; i < c.cascade_patch_sizes_m.size(); ++i) {
    const bool last = i + 1 == c.cascade_patch_sizes_m.size();
    // (M.7.1): hand over at half this cascade's Nyquist wavenumber π·N/L.
    const double k_max =
        last ? std::numeric_limits<double>::infinity() : 0.5 * kPi * n / c.cascade_patch_sizes_m[i];
    bands.push_back({k_min, k_max});
    k_min = k_max;
  }
  return bands;
}

InitialSpectrumParams cascade_spectrum_params(const SimulationConfig& c, std::size_t index) {
  const std::array<double, 2> band = cascade_bands(c)[index];
  return {.grid = {.resolution = c.resolution, .patch_size_m = c.cascade_patch_sizes_m[index]},
          .seed = c.seed + 0x9e3779b9ULL * index,
          .convention = c.convention,
          .loop_period_s = c.loop_period_s,
          .k_min_radpm = band[0],
          .k_max_radpm = band[1]};
}

void allocate_frame(const SimulationConfig& config, Frame& frame) {
  const auto texels =
      static_cast<std::size_t>(config.resolution) * static_cast<std::size_t>(config.resolution);
  frame.cascades.resize(config.cascade_patch_sizes_m.size());
  for (std::size_t c = 0; c < frame.cascades.size(); ++c) {
    CascadeFrame& f = frame.cascades[c];
    f.resolution = config.resolution;
    f.patch_size_m = config.cascade_patch_sizes_m[c];
    f.displacement.assign(3 * texels, 0.0f);
    f.displacement_half.assign(4 * texels, 0);
    const auto optional = [](LargeVector<float>& v, bool wanted, std::size_t count, float value) {
      if (wanted) {
        v.assign(count, value);
      } else {
        LargeVector<float>().swap(v);  // empty, its memory released
      }
    };
    optional(f.normal, config.outputs.normal, 3 * texels, 0.0f);
    optional(f.jacobian, config.outputs.jacobian, texels, 1.0f);
    optional(f.foam, config.outputs.foam, texels, 0.0f);
    f.packed_mips.assign(mip_chain_texels(config.resolution), 0u);
  }
}

std::size_t mip_chain_texels(int resolution) {
  const auto n = static_cast<std::size_t>(resolution);
  return (4 * n * n - 1) / 3;
}

std::size_t mip_offset(int resolution, int level) {
  const int log2n = std::countr_zero(static_cast<unsigned>(resolution));
  // offset(m) = (4N² − 1)/3 − (4^(log2 N + 1 − m) − 1)/3   (Aebi, VR Ocean, eq. 55)
  const std::size_t remaining = ((std::size_t{1} << (2 * (log2n + 1 - level))) - 1) / 3;
  return mip_chain_texels(resolution) - remaining;
}

}  // namespace ocean
