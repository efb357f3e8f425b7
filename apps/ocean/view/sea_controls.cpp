// The panel's editable sea state and grid (see sea_controls.hpp).
#include "view/sea_controls.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "ocean/plan.hpp"
#include "ocean/spectrum.hpp"

namespace ocean::cli::view {
namespace {

bool is_set(double v) { return !std::isnan(v); }

}  // namespace

SeaControls sea_controls(const SimulationConfig& c) {
  SeaControls s;
  const FrequencySpectrumParams& p = c.sea.wind_sea.spectrum;
  s.model = static_cast<int>(p.model);
  s.from_wind = !is_set(p.significant_wave_height_m);
  if (is_set(p.wind_speed_mps)) s.wind_speed_mps = p.wind_speed_mps;
  if (is_set(p.fetch_m)) s.fetch_km = p.fetch_m / 1000.0;
  if (is_set(p.significant_wave_height_m)) s.hs_m = p.significant_wave_height_m;
  if (is_set(p.peak_period_s)) s.tp_s = p.peak_period_s;
  const double depth = std::isfinite(p.depth_m) ? p.depth_m : c.sea.dispersion.depth_m;
  s.deep_water = !std::isfinite(depth);
  if (!s.deep_water) s.depth_m = depth;
  s.direction_deg = c.sea.wind_sea.direction_rad * 180.0 / std::numbers::pi;
  s.choppiness = c.choppiness;
  s.resolution = std::clamp(c.resolution, kPanelResolutions.front(), kPanelResolutions.back());
  s.cascades = std::clamp(static_cast<int>(c.cascade_patch_sizes_m.size()), 1, kMaxPanelCascades);
  // Sizes beyond the configured ones continue the default ratio of ≈ 1/4.3, so adding a cascade
  // starts from a valid (smaller) size.
  double size = 1000.0;
  for (int i = 0; i < kMaxPanelCascades; ++i) {
    const auto u = static_cast<std::size_t>(i);
    size = u < c.cascade_patch_sizes_m.size() ? c.cascade_patch_sizes_m[u] : size / 4.3;
    s.cascade_sizes_m[u] = size;
  }
  s.seed = static_cast<std::int64_t>(std::min<std::uint64_t>(c.seed, 9'000'000'000'000'000ull));
  s.loop_period_s = c.loop_period_s;
  return s;
}

Result<SimulationConfig> to_config(const SeaControls& s, const SimulationConfig& base) {
  if (s.model < 0 || s.model >= static_cast<int>(kSpectrumModelLabels.size()))
    return invalid_argument("spectrum model index " + std::to_string(s.model) + " is unknown");
  if (s.cascades < 1 || s.cascades > kMaxPanelCascades)
    return invalid_argument("cascades = " + std::to_string(s.cascades) +
                            " is out of range: must be 1 to 8 patch sizes");
  if (s.seed < 0) return invalid_argument("seed = " + std::to_string(s.seed) + " must be ≥ 0");
  SimulationConfig c = base;
  FrequencySpectrumParams& p = c.sea.wind_sea.spectrum;
  p.model = static_cast<SpectrumModel>(s.model);
  const bool jonswap_family = p.model == SpectrumModel::jonswap || p.model == SpectrumModel::tma;
  const bool from_wind = s.from_wind || p.model == SpectrumModel::phillips;
  p.wind_speed_mps = from_wind ? s.wind_speed_mps : kUnset;
  p.fetch_m = from_wind && jonswap_family ? s.fetch_km * 1000.0 : kUnset;
  p.significant_wave_height_m = from_wind ? kUnset : s.hs_m;
  p.peak_period_s = from_wind ? kUnset : s.tp_s;
  if (!jonswap_family) p.gamma = kUnset;
  if (p.model != SpectrumModel::phillips) {
    p.phillips_amplitude = kUnset;
    p.small_wave_cutoff_m = 0.0;
  }
  const double depth = s.deep_water ? kInfiniteDepth : s.depth_m;
  p.depth_m = p.model == SpectrumModel::tma ? depth : kInfiniteDepth;
  c.sea.dispersion.depth_m = depth;
  c.sea.wind_sea.direction_rad = s.direction_deg * std::numbers::pi / 180.0;
  c.choppiness = s.choppiness;
  c.resolution = s.resolution;
  c.cascade_patch_sizes_m.assign(s.cascade_sizes_m.begin(), s.cascade_sizes_m.begin() + s.cascades);
  c.seed = static_cast<std::uint64_t>(s.seed);
  c.loop_period_s = s.loop_period_s;
  if (Result<SimulationPlan> plan = SimulationPlan::make(c); !plan.ok()) return plan.status();
  return c;
}

}  // namespace ocean::cli::view
