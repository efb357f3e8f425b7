// Sea state: wave systems (wind sea + optional swell) and the wave-vector spectrum F(k) obtained
// by the ω→k change of variables.
//
// This work is based on:
//   - Horvath, C. J. (2015) Empirical directional wave spectra for computer graphics. DigiPro '15,
//     §4: F(k, θ) = S(ω(k))·D(ω, θ)·(dω/dk)/k; Vincevičius 2024, eq. 1.15 (there with Horvath's
//     factor 2 and the grid cell area folded in; here those live in the amplitude convention,
//     M.6.2).
//   - Holthuijsen, L. H. (2007) Waves in Oceanic and Coastal Waters, §3.5 (Jacobian of the
//     transformation, dkx·dkz = k·dk·dθ).
// Equations: docs/math.md §5.
#include <cmath>

#include "ocean/spectrum.hpp"

namespace ocean {

Result<WaveSystem> WaveSystem::make(const WaveSystemParams& params) {
  Result<FrequencySpectrum> spectrum = FrequencySpectrum::make(params.spectrum);
  if (!spectrum.ok()) return spectrum.status();
  const SpreadingContext context{.omega_p = spectrum.value().peak_omega(),
                                 .wind_speed_mps = params.spectrum.wind_speed_mps,
                                 .gravity_mps2 = params.spectrum.gravity_mps2};
  Result<Spreading> spreading = Spreading::make(params.spreading, context);
  if (!spreading.ok()) return spreading.status();
  if (Status s = require_finite("direction_rad", params.direction_rad); !s.ok()) return s;
  return WaveSystem(std::move(spectrum).value(), std::move(spreading).value(),
                    params.direction_rad);
}

Result<SeaState> SeaState::make(const SeaStateParams& params) {
  DispersionParams dispersion = params.dispersion;
  const FrequencySpectrumParams& wind = params.wind_sea.spectrum;
  if (wind.model == SpectrumModel::tma && std::isfinite(wind.depth_m)) {
    // The ω→k conversion must use the depth that attenuates the spectrum.
    if (std::isinf(dispersion.depth_m)) {
      dispersion.depth_m = wind.depth_m;
    } else if (dispersion.depth_m != wind.depth_m) {
      return invalid_argument("dispersion depth_m = " + format_number(dispersion.depth_m) +
                              " differs from the tma depth_m = " + format_number(wind.depth_m) +
                              ": use one depth");
    }
  }
  if (dispersion.gravity_mps2 != wind.gravity_mps2) {
    return invalid_argument("dispersion gravity_mps2 = " + format_number(dispersion.gravity_mps2) +
                            " differs from the spectrum's gravity_mps2 = " +
                            format_number(wind.gravity_mps2) + ": use one gravity");
  }
  Result<Dispersion> d = Dispersion::make(dispersion);
  if (!d.ok()) return d.status();
  std::vector<WaveSystem> systems;
  Result<WaveSystem> wind_sea = WaveSystem::make(params.wind_sea);
  if (!wind_sea.ok()) return wind_sea.status();
  systems.push_back(std::move(wind_sea).value());
  if (params.has_swell) {
    Result<WaveSystem> swell = WaveSystem::make(params.swell);
    if (!swell.ok()) return Status(swell.status().code(), "swell: " + swell.status().message());
    systems.push_back(std::move(swell).value());
  }
  return SeaState(std::move(systems), std::move(d).value());
}

double SeaState::wave_vector_spectrum(double kx, double kz) const {
  const double k = std::hypot(kx, kz);
  // Outside the dispersion domain (M.2.5) F is 0 in double precision: below kMinWavenumber,
  // ω(k) < 1e-99 rad/s, and every valid spectrum's exp(−β·(ω_ref/ω)⁴) with ω_ref > 1e-3 rad/s
  // is e^(−10³⁸⁰); above kMaxWavenumber, ω > 3e99 rad/s and S(ω) < 1e20·ω⁻⁵ < 1e-470.
  if (!(k >= Dispersion::kMinWavenumber && k <= Dispersion::kMaxWavenumber)) return 0.0;
  const double omega = dispersion_.omega(k);
  const double jacobian = dispersion_.group_velocity(k) / k;  // (dω/dk)/k
  const double heading = std::atan2(kz, kx);
  double f = 0.0;
  for (const WaveSystem& system : systems_) {
    f += system.spectrum()(omega) * system.spreading()(omega, heading - system.direction_rad());
  }
  return f * jacobian;  // (M.5.1)
}

double SeaState::variance_m2() const {
  double m0 = 0.0;
  for (const WaveSystem& system : systems_) m0 += system.spectrum().moment(0);
  return m0;
}

}  // namespace ocean
