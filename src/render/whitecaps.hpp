// The sea's whitecaps drawn as patches (src/render, private; docs/rendering.md R.11b): the sines
// of the Gaussian field that decides where each cascade's breaking probability is white
// (shaders/whitecaps.h), handed to the shaders as FrameUniforms::whitecaps with their phases at
// the camera and the frame's time.
#pragma once

#include <array>
#include <cmath>
#include <numbers>
#include <optional>

#include "ocean/plan.hpp"
#include "pass.hpp"

namespace ocean::render {

/// One sine of the field g: wave vector (rad/m), amplitude (of a unit-variance sum), angular
/// frequency by deep-water dispersion ω = √(g·k) (so the patches move and change as waves of
/// their length do) and phase at the origin and t = 0.
struct WhitecapWave {
  double kx_radpm = 0.0, kz_radpm = 0.0, amplitude = 0.0, omega_radps = 0.0, phase_rad = 0.0;
};

/// The phase speeds of the field's longest and shortest sines, as fractions of the wind speed U10:
/// the speeds of breaking crests seen from aircraft scale with the wind (Kleiss & Melville 2010),
/// and a crest moving at c is a wave of length 2π·c²/g. The longest sines (c = 0.6·U10: 23 m at
/// 10 m/s, 92 m at 20 m/s) set the patches' size; the field goes on a decade further in length
/// (c = 0.2·U10/√10: 0.26 m at 10 m/s) so that their edges are ragged and holed as foam's are.
/// A chosen range, not a law.
inline constexpr double kWhitecapSpeedLong = 0.6, kWhitecapSpeedShort = 0.2 / 3.1622776601683795;
/// The sines' share of the variance per unit ln k falls as k^−½ from the 0.6·U10 wave: the
/// patches' outlines carry more of it than the raggedness of their edges.
inline constexpr double kWhitecapSpectrumSlope = -0.5;
/// Below that wave the field goes on to waves 8 times longer with a share rising as k¹: a few
/// long sines of their own would place the patches on a visible lattice (a narrow band's troughs
/// repeat), these gather them into groups as a sea's wave groups gather its breakers.
inline constexpr double kWhitecapGroupLengths = 8.0, kWhitecapGroupSlope = 1.0;
/// The sines' directions lie within this angle either side of the wind (whitecaps are longer
/// along the crests, across the wind); isotropic where the sea names no wind.
inline constexpr double kWhitecapSpreadRad = std::numbers::pi / 3.0;

/// The field's OCEAN_RENDER_WHITECAP_WAVES sines for a sea of wind speed `u10_mps` blowing along
/// the unit vector `wind` ((0, 0): no direction, the sines spread over every direction): lengths
/// spaced evenly in ln k between the speeds above, directions and phases from additive recurrences
/// (golden ratio, plastic number), amplitudes A_i ∝ (k_i/k_0)^(slope/2) (k_0 of the 0.6·U10 wave,
/// each side its slope) scaled so that
/// Σ A²/2 = 1 (unit variance). The vectors lie on no lattice: the field does not repeat with the
/// cascades, so that from altitude the whitecaps do not show their period (the hex tiles hide it,
/// R.14), and a camera whole periods away sees another realisation of the same statistics.
inline std::array<WhitecapWave, OCEAN_RENDER_WHITECAP_WAVES> whitecap_waves(
    double u10_mps, std::array<double, 2> wind) {
  constexpr int kWaves = OCEAN_RENDER_WHITECAP_WAVES;
  constexpr double kG = 9.80665, kTwoPi = 2.0 * std::numbers::pi;
  const double c_long = kWhitecapSpeedLong * u10_mps, c_short = kWhitecapSpeedShort * u10_mps;
  const double k_peak = kG / (c_long * c_long), k_high = kG / (c_short * c_short);  // c² = g/k
  const double k_low = k_peak / kWhitecapGroupLengths;
  const bool directed = wind[0] != 0.0 || wind[1] != 0.0;
  const double base = directed ? std::atan2(wind[1], wind[0]) : 0.0;
  std::array<WhitecapWave, kWaves> waves{};
  double variance = 0.0;
  for (int i = 0; i < kWaves; ++i) {
    const double k = k_low * std::pow(k_high / k_low, (i + 0.5) / kWaves);
    const double u = std::fmod(0.5 + i * 0.6180339887498949, 1.0);   // golden ratio
    const double p = std::fmod(0.25 + i * 0.7548776662466927, 1.0);  // plastic number
    const double angle = directed ? base + (2.0 * u - 1.0) * kWhitecapSpreadRad : kTwoPi * u;
    const double amplitude =
        std::pow(k / k_peak, 0.5 * (k >= k_peak ? kWhitecapSpectrumSlope : kWhitecapGroupSlope));
    variance += 0.5 * amplitude * amplitude;
    waves[static_cast<std::size_t>(i)] = {k * std::cos(angle), k * std::sin(angle), amplitude,
                                          std::sqrt(kG * k), kTwoPi * p};
  }
  for (WhitecapWave& w : waves) w.amplitude /= std::sqrt(variance);
  return waves;
}

/// The field's sines for a described sea, scaled with its wind: U10 = |drift|/kWindDriftFraction
/// along the drift where the sea names its wind; otherwise the wind of a fully developed sea of
/// height Hs, Hs = 0.21·U²/g (Pierson & Moskowitz 1964), with no direction. Empty where that
/// wind is not a positive finite speed (a flat sea).
inline std::optional<std::array<WhitecapWave, OCEAN_RENDER_WHITECAP_WAVES>> whitecap_waves(
    const SurfaceDescription& surface) {
  const double drift = std::hypot(surface.foam_drift_mps[0], surface.foam_drift_mps[1]);
  const double u10 = drift > 0.0 ? drift / kWindDriftFraction
                                 : std::sqrt(9.80665 * surface.significant_wave_height_m / 0.21);
  if (!(u10 > 0.0 && std::isfinite(u10))) return std::nullopt;
  return whitecap_waves(u10, drift > 0.0 ? std::array<double, 2>{surface.foam_drift_mps[0] / drift,
                                                                 surface.foam_drift_mps[1] / drift}
                                         : std::array<double, 2>{0.0, 0.0});
}

// render pass 255: WhitecapPass — the sea's whitecaps drawn as patches (R.11b)
struct WhitecapPass : Pass {
  std::array<WhitecapWave, OCEAN_RENDER_WHITECAP_WAVES> waves{};  // from configure()
  bool enabled = false;  // a breaking source (weighted foam) and a wind speed above zero

  void fill_uniforms(const Renderer::State& st, const View& view, shader::FrameUniforms& u) const;
};

}  // namespace ocean::render
