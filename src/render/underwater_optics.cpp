// The water's optics seen from below on the CPU (ocean/underwater.hpp; docs/rendering.md R.50,
// R.51, R.54): the Fresnel transmittance of Snell's window, which shaders/underwater.glsl
// restates, and the visibility its beam attenuation gives. No device code.
//
// This work is based on:
// - E. Hecht, "Optics", 4th ed., 2002, §4.6: the Fresnel amplitude coefficients
//   r_s, r_p; unpolarised reflectance (r_s² + r_p²)/2.
// - R. J. Davies-Colley, "Measuring water clarity with a black disk", Limnology and Oceanography
//   33(4), 1988; J. R. V. Zaneveld and W. S. Pegau, "Robust underwater visibility parameter",
//   Optics Express 11(23), 2003: the horizontal sighting range of a black target, V = 4.8/c.
#include <algorithm>
#include <cmath>

#include "ocean/underwater.hpp"

namespace ocean::render {

double water_to_air_transmittance(double cos_incidence) {
  const double ci = std::clamp(cos_incidence, 0.0, 1.0), n = kWaterIor;
  const double sin_t_sq = n * n * (1.0 - ci * ci);
  if (sin_t_sq >= 1.0) return 0.0;  // total internal reflection
  const double ct = std::sqrt(1.0 - sin_t_sq);
  const double r_s = (n * ci - ct) / (n * ci + ct), r_p = (n * ct - ci) / (n * ct + ci);
  return 1.0 - 0.5 * (r_s * r_s + r_p * r_p);
}

double visibility_m(double absorption_per_m, double scattering_per_m) {
  return kBlackTargetVisibilityProduct / beam_attenuation_per_m(absorption_per_m, scattering_per_m);
}

}  // namespace ocean::render
