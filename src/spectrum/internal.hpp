// Helpers shared between the spectrum module's translation units (not installed).
#pragma once

#include "ocean/spectrum.hpp"

namespace ocean {

/// scale·r⁵·exp(−β·r⁴) for r ≥ 0 (r = ω_ref/ω; 0 at r = 0 and r = ∞), the form every
/// Pierson–Moskowitz-type spectrum shares (M.3.1, M.3.3, M.3.7, M.3.11); 0 < scale < 1e20.
/// Finite for every r, and 0 exactly, through the denormals, where the value is below the
/// smallest double.
double pm_spectrum(double scale, double r, double beta);
/// Water depth h ∈ [1e-100, ∞] (the dispersion domain, M.2.5), else "depth_m = ... is out of
/// range: ...".
Status require_depth(double depth_m);
double pierson_moskowitz_peak_omega(double wind_speed_mps, double gravity_mps2);
double pierson_moskowitz_alpha();
double pierson_moskowitz_beta();
double jonswap_peak_enhancement(double omega, double omega_p, double gamma, double sigma_a,
                                double sigma_b);
/// Phillips variance density per unit k-area before spreading, A·e^(−1/(kL)²)·e^(−k²l²)/k⁴, m⁴
/// (multiplied by a normalised D(θ) it is F(k)).
double phillips_k_density(double k, double amplitude, double wind_speed_mps, double gravity_mps2,
                          double small_wave_cutoff_m);
/// Phillips frequency spectrum in deep water, S(ω) = A·e^(−1/(kL)²)·e^(−k²l²)/k³·dk/dω with
/// k = ω²/g, i.e. 2A·g²/ω0⁵·r⁵·e^(−r⁴)·e^(−k²l²) with ω0 = g/U and r = ω0/ω, m²·s/rad (M.3.11).
double phillips_omega_density(double omega, double amplitude, double wind_speed_mps,
                              double gravity_mps2, double small_wave_cutoff_m);
/// Default Phillips amplitude: α_PM/(2β_PM), so m0 = A·L²/2 equals Pierson–Moskowitz's.
double phillips_default_amplitude();

}  // namespace ocean
