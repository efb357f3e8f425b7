// view/sea_controls.hpp — what the `ocean view` panel edits of a SimulationConfig: the wind
// sea's spectrum model and sea state, direction, depth, and the grid (resolution, cascades,
// seed, loop period, choppiness). Plain values that widgets can point at; to_config() turns them
// back into a configuration, leaving every other field (swell, spreading, foam, ...) as it was.
#pragma once

#include <array>
#include <cstdint>

#include "ocean/lod.hpp"
#include "ocean/sim.hpp"

namespace ocean::cli::view {

/// The names of a library table as C strings for a combo box, in table order (the tables are in
/// enum order, so combo index = enum value).
template <class E, std::size_t N>
constexpr std::array<const char*, N> combo_labels(const std::array<EnumName<E>, N>& table) {
  std::array<const char*, N> labels{};
  for (std::size_t i = 0; i < N; ++i) labels[i] = table[i].name.data();
  return labels;
}
/// The spectrum models the panel offers.
inline constexpr std::array<const char*, kSpectrumModelNames.size()> kSpectrumModelLabels =
    combo_labels(kSpectrumModelNames);
/// The LOD quality presets the panel offers.
inline constexpr std::array<const char*, lod::kQualityPresetNames.size()> kQualityPresetLabels =
    combo_labels(lod::kQualityPresetNames);
/// Resolutions the panel offers: powers of two 64..512 (combo index i → 64·2^i).
inline constexpr std::array<int, 4> kPanelResolutions = {64, 128, 256, 512};
inline constexpr int kMaxPanelCascades = 8;  ///< SimulationConfig allows 1..8 cascades

struct SeaControls {
  int model = 1;          ///< index into kSpectrumModelLabels
  bool from_wind = true;  ///< wind (+ fetch for jonswap/tma); false: Hs and Tp
  double wind_speed_mps = 10.0;
  double fetch_km = 100.0;  ///< jonswap/tma from wind
  double hs_m = 2.0, tp_s = 8.0;
  bool deep_water = true;  ///< false: depth_m applies (dispersion, and TMA's attenuation)
  double depth_m = 20.0;
  double direction_deg = 0.0;  ///< towards which the waves travel, from +x towards +z
  double choppiness = 1.0;
  int resolution = 256;
  int cascades = 3;  ///< 1..kMaxPanelCascades; the first `cascades` sizes apply
  std::array<double, kMaxPanelCascades> cascade_sizes_m{};
  std::int64_t seed = 1;
  double loop_period_s = 200.0;
};

/// The controls showing `config`. Values the panel cannot show (a resolution outside 64..512,
/// Hs/Tp for one form while the other is set) get the nearest shown value or a default of the
/// other form, so switching forms starts from something sensible.
SeaControls sea_controls(const SimulationConfig& config);

/// `base` with the controls applied and validated (SimulationPlan::make: validate, sea state):
/// invalid_argument naming the field otherwise, e.g. when a cascade is not smaller than the
/// previous one. Phillips is always given by wind; fetch is set only for jonswap/tma from wind;
/// gamma, the Phillips amplitude and cutoff are kept only for the models they apply to.
Result<SimulationConfig> to_config(const SeaControls& controls, const SimulationConfig& base);

}  // namespace ocean::cli::view
