// The shallows scenes (see shallows.hpp).
#include "shallows.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>
#include <utility>

#include "ocean/shore_wave.hpp"
#include "ocean/spectrum.hpp"

namespace ocean::cli {
namespace {

// A square map of side `size` and `n` samples per side, centred on `centre`, whose value is
// f(distance from the centre).
template <typename F>
waves::PlacedMap radial_map(std::array<double, 2> centre, double size, int n, F f) {
  auto map = std::make_shared<waves::HeightMap>();
  map->rows = n, map->cols = n;
  map->values.resize(static_cast<std::size_t>(n) * static_cast<std::size_t>(n));
  const double cell = size / n;
  for (int r = 0; r < n; ++r) {
    for (int c = 0; c < n; ++c) {
      const double dx = (c + 0.5) * cell - 0.5 * size, dz = (r + 0.5) * cell - 0.5 * size;
      map->values[static_cast<std::size_t>(r) * static_cast<std::size_t>(n) +
                  static_cast<std::size_t>(c)] = static_cast<float>(f(std::hypot(dx, dz)));
    }
  }
  return {.map = std::move(map),
          .origin_m = {centre[0] - 0.5 * size, centre[1] - 0.5 * size},
          .size_m = size};
}

// The beach's depth at a distance u along its normal from the centre (shallows.hpp).
double beach_depth(double u) {
  constexpr double kToe_m = kBeachShore_m - 200.0;  // where the 1:20 slope is 10 m deep
  if (u > kBeachShore_m) return -std::min((u - kBeachShore_m) / 20.0, 3.0);  // the land
  if (u > kToe_m) return (kBeachShore_m - u) / 20.0;
  return std::min(10.0 + (kToe_m - u) / 4.0, kBeachDeep_m);
}

waves::PlacedMap beach_map(std::array<double, 2> centre, int n) {
  auto map = std::make_shared<waves::HeightMap>();
  map->rows = n, map->cols = n;
  map->values.resize(static_cast<std::size_t>(n) * static_cast<std::size_t>(n));
  const double cell = kBeachSize_m / n, phi = kBeachNormal_deg * std::numbers::pi / 180.0;
  for (int r = 0; r < n; ++r) {
    for (int c = 0; c < n; ++c) {
      const double dx = (c + 0.5) * cell - 0.5 * kBeachSize_m;
      const double dz = (r + 0.5) * cell - 0.5 * kBeachSize_m;
      map->values[static_cast<std::size_t>(r) * static_cast<std::size_t>(n) +
                  static_cast<std::size_t>(c)] =
          static_cast<float>(beach_depth(dx * std::cos(phi) + dz * std::sin(phi)));
    }
  }
  return {.map = std::move(map),
          .origin_m = {centre[0] - 0.5 * kBeachSize_m, centre[1] - 0.5 * kBeachSize_m},
          .size_m = kBeachSize_m};
}

waves::PlacedMap lagoon_map(std::array<double, 2> centre) {
  return radial_map(centre, 400.0, 256, [](double r) {
    if (r > kLagoonReef_m)  // the reef wall, down to optically deep water by the map's edge
      return std::min(20.0 + (kLagoonDeep_m - 20.0) * (r - kLagoonReef_m) / 50.0, kLagoonDeep_m);
    return std::max((r - kLagoonShore_m) / 5.0, -kLagoonIslandHeight_m);
  });
}

double smoothstep(double e0, double e1, double x) {
  const double t = std::clamp((x - e0) / (e1 - e0), 0.0, 1.0);
  return t * t * (3.0 - 2.0 * t);
}

}  // namespace

std::optional<Shallows> parse_shallows(std::string_view name) {
  if (name == "none") return Shallows::none;
  if (name == "lily-pads") return Shallows::lily_pads;
  if (name == "lagoon") return Shallows::lagoon;
  if (name == "beach") return Shallows::beach;
  return std::nullopt;
}

Result<std::optional<waves::Damping>> shallows_damping(Shallows scene,
                                                       std::array<double, 2> centre_m,
                                                       const SimulationConfig& config,
                                                       double breaking_index) {
  if (scene == Shallows::none) return std::optional<waves::Damping>{};
  waves::DampingParams params{.band_wavenumbers_radpm = band_wavenumbers(config),
                              .gravity_mps2 = config.sea.dispersion.gravity_mps2};
  if (scene == Shallows::lily_pads) {
    params.mask =
        radial_map(centre_m, 200.0, 256, [](double r) { return smoothstep(40.0, 60.0, r); });
  } else {
    params.bathymetry = scene == Shallows::lagoon ? lagoon_map(centre_m) : beach_map(centre_m, 512);
    if (breaking_index != 0.0) {  // the surf (W.25–W.27)
      Result<std::vector<double>> m0 = band_variances(config);
      if (!m0.ok()) return m0.status();
      params.band_variances_m2 = std::move(m0).value();
      params.breaking_index = breaking_index;
    }
  }
  Result<waves::Damping> made = waves::Damping::make(std::move(params));
  if (!made.ok()) return made.status();
  return std::optional<waves::Damping>(std::move(made).value());
}

Result<std::optional<waves::Waveform>> shallows_shore_wave(Shallows scene,
                                                           std::array<double, 2> centre_m,
                                                           const SimulationConfig& config,
                                                           double breaking_index, int resolution,
                                                           int frames) {
  if (scene != Shallows::lagoon && scene != Shallows::beach)
    return std::optional<waves::Waveform>{};
  // The sea's peak wave: the peak period and mean direction of the system holding the most
  // variance, and the low band's rms height (W.38).
  Result<WaveSystem> system = WaveSystem::make(config.sea.wind_sea);
  if (!system.ok()) return system.status();
  if (config.sea.has_swell) {
    Result<WaveSystem> swell = WaveSystem::make(config.sea.swell);
    if (!swell.ok()) return swell.status();
    if (swell.value().spectrum().moment(0) > system.value().spectrum().moment(0))
      system = std::move(swell);
  }
  Result<std::vector<double>> m0 = band_variances(config);
  if (!m0.ok()) return m0.status();
  const double g = config.sea.dispersion.gravity_mps2;
  const double k_low = band_wavenumbers(config).front();
  const waves::PlacedMap depth =
      scene == Shallows::lagoon ? lagoon_map(centre_m) : beach_map(centre_m, 512);
  Result<waves::ShoreWave> made = waves::ShoreWave::make({
      .bathymetry = depth,
      .period_s = 2.0 * std::numbers::pi / system.value().spectrum().peak_omega(),
      .deep_height_m = std::sqrt(8.0 * m0.value().front()),
      .direction_deg = system.value().direction_rad() * 180.0 / std::numbers::pi,
      .gravity_mps2 = g,
      .breaking_index = breaking_index == 0.0 ? waves::kMcCowanBreakingIndex : breaking_index,
  });
  if (!made.ok()) return made.status();
  const waves::ShoreWave& wave = made.value();
  const double period = wave.params().period_s, size = depth.size_m, cell = size / resolution;
  const auto n = static_cast<std::size_t>(resolution);
  // Each cell's amplitude β·H/2 and phase S, once; β the share of the low band's amplitude the
  // depth law takes out (W.38).
  std::vector<double> amplitude(n * n), phase(n * n);
  for (std::size_t r = 0; r < n; ++r) {
    for (std::size_t c = 0; c < n; ++c) {
      const double x = depth.origin_m[0] + (static_cast<double>(c) + 0.5) * cell;
      const double z = depth.origin_m[1] + (static_cast<double>(r) + 0.5) * cell;
      const waves::ShoreWavePoint q = wave.at(x, z);
      const double w0 = waves::depth_band_weight(k_low, std::max(q.depth_m, 0.0), g);
      amplitude[r * n + c] = std::sqrt(std::max(0.0, 1.0 - w0 * w0)) * 0.5 * q.height_m;
      phase[r * n + c] = q.phase_rad;
    }
  }
  waves::Waveform form{.fps_hz = frames / period,
                       .playback = waves::Playback::loop,
                       .x_m = depth.origin_m[0] + 0.5 * size,
                       .z_m = depth.origin_m[1] + 0.5 * size,
                       .size_m = size,
                       .amplitude_m = 1.0};
  for (int f = 0; f < frames; ++f) {
    auto map = std::make_shared<waves::HeightMap>();
    map->rows = map->cols = resolution;
    map->values.resize(n * n);
    const double omega_t = wave.omega_radps() * period * f / frames;
    for (std::size_t i = 0; i < n * n; ++i)  // (W.37), heights only
      map->values[i] = static_cast<float>(amplitude[i] * std::cos(phase[i] - omega_t));
    form.frames.push_back(std::move(map));
  }
  return std::optional<waves::Waveform>(std::move(form));
}

}  // namespace ocean::cli
