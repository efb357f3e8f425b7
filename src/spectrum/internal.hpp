// Helpers shared between the spectrum module's translation units (not installed).
#pragma once

#include "ocean/spectrum.hpp"

namespace ocean {

double pierson_moskowitz_peak_omega(double wind_speed_mps, double gravity_mps2);
double pierson_moskowitz_alpha();
double pierson_moskowitz_beta();
double jonswap_peak_enhancement(double omega, double omega_p, double gamma, double sigma_a,
                                double sigma_b);
/// Phillips variance density per unit k-area before spreading, A·e^(−1/(kL)²)·e^(−k²l²)/k⁴, m⁴
/// (multiplied by a normalised D(θ) it is F(k)).
double phillips_k_density(double k, double amplitude, double wind_speed_mps, double gravity_mps2,
                          double small_wave_cutoff_m);
/// Default Phillips amplitude: α_PM/(2β_PM), so m0 = A·L²/2 equals Pierson–Moskowitz's.
double phillips_default_amplitude();

}  // namespace ocean
