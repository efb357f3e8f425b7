// ocean/underwater.hpp — the water's optics below the surface (docs/rendering.md R.50–R.52):
// what a camera under the sea sees. The absorption is the seabed's (Seabed::absorption_per_m,
// pure water after Pope & Fry 1997), so the bed seen from above and the water seen from below
// fade by one law; this adds the scattering that gives the water its fog.
#pragma once

#include "ocean/core.hpp"

namespace ocean::render {

/// The water seen from below. A camera whose near plane lies under the surface sees the underside
/// of the waves (the sky refracted inside Snell's window, total internal reflection beyond the
/// critical angle arcsin(1/1.333) = 48.6°) and everything through a fog of the water's own
/// light: L = L₀·e^{−(a+b)·r} + L∞·(1 − e^{−(a+b)·r}) over a path r (R.51).
struct Underwater {
  /// Scattering coefficient b of the water, 1/m, [0, 10], the same for every channel: Morel's
  /// (1988, eq. 12) b(550 nm) = 0.30·C^0.62 for a chlorophyll concentration C = 0.1 mg/m³
  /// (clear open ocean) is 0.072 m⁻¹. Larger: murkier water, a shorter view.
  double scattering_per_m = 0.072;
};
/// invalid_argument naming the field for a value outside the range above or not finite.
Status validate(const Underwater& underwater);

/// The refractive index of sea water the view from below uses (R.50).
inline constexpr double kWaterIor = 1.333;

/// Water-to-air transmittance T = 1 − (r_s² + r_p²)/2 of the unpolarised Fresnel equations at the
/// cosine of the angle of incidence in the water (R.50): 0.980 at normal incidence, 0 from the
/// critical angle arcsin(1/1.333) = 48.6° on (total internal reflection). The shaders' Snell's
/// window box-filters this function over each pixel (shaders/underwater.glsl).
double water_to_air_transmittance(double cos_incidence);

/// Beam attenuation c = a + b, 1/m, of one channel (R.51): the fog's e^{−c·r}.
inline double beam_attenuation_per_m(double absorption_per_m, double scattering_per_m) {
  return absorption_per_m + scattering_per_m;
}

/// The distance at which a black target seen horizontally under water disappears, m (R.54):
/// V = 4.8/c (Davies-Colley 1988; Zaneveld & Pegau 2003), c the beam attenuation at 550 nm, the
/// green channel. With the defaults (Seabed::absorption_per_m[1] = 0.0565 m⁻¹ of pure water and
/// b = 0.072 m⁻¹ of clear open ocean) 37 m.
inline constexpr double kBlackTargetVisibilityProduct = 4.8;
double visibility_m(double absorption_per_m, double scattering_per_m);

}  // namespace ocean::render
