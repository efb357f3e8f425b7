// ocean/underwater.hpp — the water's optics below the surface (docs/rendering.md R.50–R.52):
// what a camera under the sea sees. The absorption is the seabed's (Seabed::absorption_per_m,
// pure water after Pope & Fry 1997), so the bed seen from above and the water seen from below
// fade by one law; this adds the scattering that gives the water its fog.
#pragma once

#include <array>
#include <functional>

#include "ocean/core.hpp"

namespace ocean::render {

/// The water seen from below. A camera whose near plane lies under the surface sees the underside
/// of the waves (the sky refracted inside Snell's window, total internal reflection beyond the
/// critical angle arcsin(1/1.333) = 48.6°) and everything through a fog of the water's own
/// light: L = L₀·e^{−(a+b)·r} + L∞·(1 − e^{−(a+b)·r}) over a path r (R.51).
struct Underwater {
  /// Scattering coefficient b of the water, 1/m, [0, 10], the same for every channel: Morel's
  /// (1988, eq. 12) b(550 nm) = 0.30·C^0.62 for a chlorophyll concentration C = 0.1 mg/m³
  /// (clear open ocean) is 0.072 m⁻¹. Larger: murkier water, a shorter view (coastal water
  /// 0.3–1 m⁻¹). `ocean render --scattering` or a preset's "underwater": {"scattering_per_m"}
  /// (preset::PictureSettings) set it; the fog (R.51), the light shafts (R.66) and the
  /// visibility (R.54) follow it.
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

/// The sea's surface gradient as the normals hold it at a horizontal point (x, z), m: s with the
/// upward normal ∝ (s_x, 1, s_z), i.e. s = −∇h.
using SlopeField = std::function<std::array<double, 2>(double x_m, double z_m)>;

/// Caustics (R.65): how many lattice points the gather takes on each side of its centre, and
/// the largest change of the refracted sun ray's horizontal tangent it holds (the ray's tilt by
/// surface slopes up to about 0.24 under a high sun).
inline constexpr int kCausticHalfWidth = 3;
inline constexpr double kCausticTilt = 0.06;
/// The finest lattice spacing, m: below it the normals' mips hold nothing finer.
inline constexpr double kCausticMinSpacing_m = 0.03;

/// The lattice spacing δ of the caustic gather at depth d, m (R.65): the largest ray deflection
/// d·kCausticTilt fits in a block of half_width points each side, δ = max(δ_min,
/// d·kCausticTilt/(half_width − 1.5)). half_width ≥ 2.
double caustic_spacing_m(double depth_m, int half_width);

/// The most the caustics may focus the sun, over a flat surface's irradiance: the ray
/// mapping's singularities (where det ∂X/∂x = 0, the bright lines) are integrable, but a pixel
/// that samples one would flash.
inline constexpr double kCausticMaxIrradiance = 100.0;

/// The sun's irradiance on a horizontal plane `depth_m` below the mean surface at (x, z), over
/// what a flat surface gives (R.65): sunlight refracted at the surface's normals (Snell, n =
/// 1.333) and carried in straight lines to the plane. A lattice of spacing δ on the surface,
/// each cell two triangles, is mapped to the plane by the refracted rays; every triangle that
/// lands over (x, z) adds its flux (its area times its vertices' mean weight w = N·L/(N_y·L_y))
/// over the area it lands on; the sum is capped at kCausticMaxIrradiance, and a point that no
/// triangle of the block covers (rays deflected beyond it) takes the mean, 1. Exactly 1 under a
/// flat surface; its mean over a period of a periodic surface is the lattice's mean w, 1 (where
/// no point is capped); for a smooth surface it tends, as δ → 0, to w/|det ∂X/∂x| of the ray
/// mapping x ↦ X (the intensity law), summed over the points whose rays cross there. `sun_dir`
/// is the unit vector towards the sun (y > 0). Mirrored by `caustic_irradiance` in
/// shaders/underwater.glsl.
double caustic_irradiance(const SlopeField& slope, const std::array<double, 3>& sun_dir, double x_m,
                          double z_m, double depth_m, double spacing_m,
                          int half_width = kCausticHalfWidth);

/// The direction of the sun's light in the water under a flat surface (R.66): Snell's law
/// refraction of −sun_dir at the normal (0, 1, 0); y < 0.
std::array<double, 3> refracted_sun(const std::array<double, 3>& sun_dir);

/// Henyey–Greenstein phase function p(cos θ) = (1 − g²)/(4π(1 + g² − 2g·cos θ)^{3/2}), 1/sr,
/// normalised over the sphere (Henyey & Greenstein 1941).
double henyey_greenstein_phase(double cos_theta, double g);
/// The asymmetry g of sea water's scattering (R.66): the mean cosine 0.924 of Petzold's (1972)
/// measured particle phase function (Mobley, "Light and Water", 1994).
inline constexpr double kWaterPhaseG = 0.924;

/// The sunlight scattered once towards an eye `depth_m` below the mean surface along a path of
/// length r looking along the unit direction `view` (R.66), under a flat surface, per unit of
/// the sun's horizontal irradiance just below the surface: b·p(θ)/μ_w·e^{−a·z_e/μ_w}·
/// (1 − e^{−κ·r})/κ, κ = a + b − a·v_y/μ_w, θ between the refracted sun and −view, μ_w its
/// cosine to the vertical. One channel; r may be infinite where κ > 0.
double sun_single_scattering(const std::array<double, 3>& sun_dir,
                             const std::array<double, 3>& view, double depth_m, double r_m,
                             double absorption_per_m, double scattering_per_m);

}  // namespace ocean::render
