// Simulation configuration: validation, cascade wavenumber bands and the mip-chain layout.
//
// Sources: Vincevičius 2024, §2.5 (cascades against tiling); Aebi, VR Ocean, eq. 55 (mip
// offsets).
// Equations: docs/math.md §7.
#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <string>

#include "ocean/sim.hpp"

namespace ocean {

std::string_view to_string(NormalMethod method) { return name_of(kNormalMethodNames, method); }

Result<NormalMethod> parse_normal_method(std::string_view name) {
  if (std::optional<NormalMethod> m = value_of(kNormalMethodNames, name)) return *m;
  return invalid_argument("normals = '" + excerpt(name) + "' is unknown: must be one of " +
                          name_list(kNormalMethodNames, ", ", ", "));
}

std::string_view to_string(BandRole role) { return name_of(kBandRoleNames, role); }

Result<std::vector<BandRole>> parse_band_roles(std::string_view list) {
  std::vector<BandRole> roles;
  std::size_t begin = 0;
  while (true) {
    const std::size_t end = std::min(list.find(',', begin), list.size());
    const std::string_view name = list.substr(begin, end - begin);
    std::optional<BandRole> role = value_of(kBandRoleNames, name);
    if (!role)
      return invalid_argument("band role '" + excerpt(name) + "' in '" + excerpt(list) +
                              "' is unknown: must be one of " +
                              name_list(kBandRoleNames, ", ", ", "));
    roles.push_back(*role);
    if (end == list.size()) return roles;
    begin = end + 1;
  }
}

namespace {
Status validate_far_noise(const FarNoiseConfig& f) {
  if (f.resolution != 0 && (f.resolution < 16 || f.resolution > 4096)) {
    return invalid_argument("far_noise.resolution = " + std::to_string(f.resolution) +
                            " is out of range: must be 0 (off) or in [16, 4096]");
  }
  if (Status s = require_in_range("far_noise.size_m", f.size_m, 1.0, 1e6); !s.ok()) return s;
  for (int i = 0; i < 2; ++i) {
    const std::string name = std::string("far_noise.origin_m[") + (i == 0 ? "0]" : "1]");
    if (Status s = require_in_range(name, f.origin_m[static_cast<std::size_t>(i)], -1e9, 1e9);
        !s.ok())
      return s;
  }
  return {};
}
}  // namespace

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
  if (!c.band_roles.empty() && c.band_roles.size() != c.cascade_patch_sizes_m.size()) {
    return invalid_argument("band_roles = " + std::to_string(c.band_roles.size()) + " roles for " +
                            std::to_string(c.cascade_patch_sizes_m.size()) +
                            " cascades: must be one per cascade (or none: every band both)");
  }
  if (Status s = require_in_range("choppiness", c.choppiness, 0.0, 10.0); !s.ok()) return s;
  if (Status s = require_in_range("loop_period_s", c.loop_period_s, 0.0, 1e6); !s.ok()) return s;
  if (Status s = require_in_range("roughness", c.roughness, 0.0, 1.0); !s.ok()) return s;
  if (!(c.foam.breaking_acceleration > 0.0 && c.foam.breaking_acceleration <= 2.0)) {
    return invalid_argument(
        "foam.breaking_acceleration = " + format_number(c.foam.breaking_acceleration) +
        " is out of range: must be in (0, 2] (a fraction of g)");
  }
  if (Status s = require_in_range("foam.jacobian_start", c.foam.jacobian_start, -10.0, 10.0);
      !s.ok()) {
    return s;
  }
  if (!(c.foam.jacobian_full < c.foam.jacobian_start) || !std::isfinite(c.foam.jacobian_full)) {
    return invalid_argument("foam.jacobian_full = " + format_number(c.foam.jacobian_full) +
                            " is out of range: must be finite and below foam.jacobian_start = " +
                            format_number(c.foam.jacobian_start));
  }
  if (Status s = require_in_range("foam.decay_per_s", c.foam.decay_per_s, 0.0, 1e6); !s.ok()) {
    return s;
  }
  if (Status s = validate_far_noise(c.far_noise); !s.ok()) return s;
  if (c.loop_period_s == 0.0) return {};
  Result<double> shortest = shortest_loop_period_s(c);
  if (!shortest.ok()) return shortest.status();
  if (c.loop_period_s >= shortest.value()) return {};
  // Shorter, the longest waves quantise to ω' = ⌊ω·T/2π⌋·2π/T = 0 (M.2.4): a frozen swell.
  const std::string rule = shortest.value() <= 1e6
                               ? "in [" + format_number(shortest.value()) + ", 1e+06]"
                               : "0 (this sea's longest waves need more than 1e+06 s)";
  return invalid_argument("loop_period_s = " + format_number(c.loop_period_s) +
                          " is too short: the longest waves (" +
                          format_number(c.cascade_patch_sizes_m.front()) +
                          " m) would stand still; must be 0 (no loop) or " + rule);
}

namespace {
// The smallest |k| of a cascade's grid inside its band [k_lo, k_hi), computed as
// make_initial_spectrum computes it (k = hypot(Δk·m, Δk·n), Nyquist row and column left out);
// 0 when the band holds no grid wave vector.
double lowest_wavenumber(int resolution, double patch_size_m, std::array<double, 2> band) {
  const double dk = 2.0 * kPi / patch_size_m;
  double lowest = std::numeric_limits<double>::infinity();
  for (int m = 0; m < resolution / 2; ++m) {
    // The first n with hypot(m, n) ≥ k_lo/Δk, give or take the rounding of the square root.
    const double reach = band[0] / dk;
    int n = static_cast<int>(std::sqrt(std::max(0.0, reach * reach - double(m) * m)));
    for (n = std::max(n - 1, 0); n < resolution / 2; ++n) {
      const double k = std::hypot(dk * m, dk * n);
      if ((m != 0 || n != 0) && k >= band[0]) {
        if (k < band[1]) lowest = std::min(lowest, k);
        break;
      }
    }
  }
  return std::isinf(lowest) ? 0.0 : lowest;
}
}  // namespace

Result<double> shortest_loop_period_s(const SimulationConfig& c) {
  Result<SeaState> sea = SeaState::make(c.sea);
  if (!sea.ok()) return sea.status();
  const Dispersion& dispersion = sea.value().dispersion();
  const std::vector<std::array<double, 2>> bands = cascade_bands(c);
  double shortest = 0.0;
  for (std::size_t i = 0; i < bands.size(); ++i) {
    const double k = lowest_wavenumber(c.resolution, c.cascade_patch_sizes_m[i], bands[i]);
    if (k == 0.0) continue;
    const double omega = dispersion.omega(k);
    // ω' > 0 needs ⌊ω·T/2π⌋ ≥ 1 (M.2.4): T ≥ 2π/ω, moved to the exact double at which
    // quantize_omega (as the spectrum evaluates it) first gives a moving wave.
    double t = 2.0 * kPi / omega;
    while (quantize_omega(omega, t) == 0.0) t = std::nextafter(t, kInfiniteDepth);
    while (quantize_omega(omega, std::nextafter(t, 0.0)) > 0.0) t = std::nextafter(t, 0.0);
    shortest = std::max(shortest, t);
  }
  return shortest;
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

std::vector<double> band_wavenumbers(const SimulationConfig& c) {
  std::vector<double> k;
  const std::vector<std::array<double, 2>> bands = cascade_bands(c);
  for (std::size_t i = 0; i < bands.size(); ++i) {
    const double lo = i == 0 ? 2.0 * kPi / c.cascade_patch_sizes_m[i] : bands[i][0];
    const double hi =
        std::isfinite(bands[i][1]) ? bands[i][1] : kPi * c.resolution / c.cascade_patch_sizes_m[i];
    k.push_back(std::sqrt(lo * hi));  // (W.14)
  }
  return k;
}

Result<std::vector<double>> band_variances(const SimulationConfig& c) {
  Result<SeaState> sea = SeaState::make(c.sea);
  if (!sea.ok()) return sea.status();
  std::vector<double> m0;
  for (std::size_t i = 0; i < c.cascade_patch_sizes_m.size(); ++i) {
    Result<std::vector<double>> power =
        expected_wave_power(sea.value(), cascade_spectrum_params(c, i));
    if (!power.ok()) return power.status();
    double sum = 0.0;
    for (double p : power.value()) sum += p;
    m0.push_back(sum);
  }
  return m0;
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
    optional(f.velocity, config.outputs.velocity, 3 * texels, 0.0f);
    f.packed_mips.assign(mip_chain_texels(config.resolution), 0u);
  }
  const FarNoiseConfig& noise = config.far_noise;
  frame.far_noise.origin_m = noise.origin_m;
  frame.far_noise.size_m = noise.size_m;
  frame.far_noise.resolution = noise.resolution;
  if (noise.resolution > 0) {
    const auto n = static_cast<std::size_t>(noise.resolution);
    frame.far_noise.height_slope.assign(3 * n * n, 0.0f);
  } else {
    LargeVector<float>().swap(frame.far_noise.height_slope);
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
