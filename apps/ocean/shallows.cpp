// The shallows scenes (see shallows.hpp).
#include "shallows.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <utility>

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

double smoothstep(double e0, double e1, double x) {
  const double t = std::clamp((x - e0) / (e1 - e0), 0.0, 1.0);
  return t * t * (3.0 - 2.0 * t);
}

}  // namespace

std::optional<Shallows> parse_shallows(std::string_view name) {
  if (name == "none") return Shallows::none;
  if (name == "lily-pads") return Shallows::lily_pads;
  if (name == "lagoon") return Shallows::lagoon;
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
    params.bathymetry = radial_map(centre_m, 400.0, 256, [](double r) {
      if (r > kLagoonReef_m)  // the reef wall, down to optically deep water by the map's edge
        return std::min(20.0 + (kLagoonDeep_m - 20.0) * (r - kLagoonReef_m) / 50.0, kLagoonDeep_m);
      return std::max((r - kLagoonShore_m) / 5.0, -kLagoonIslandHeight_m);
    });
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

}  // namespace ocean::cli
