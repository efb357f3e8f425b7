// A program outside the project that uses the installed library: evaluates the
// Pierson–Moskowitz spectrum and checks Hs against its closed form 0.2093·U²/g, and loads a
// built-in preset (the preset module's JSON dependency stays inside the library).
#include <cmath>
#include <cstdio>

#include "ocean/preset.hpp"
#include "ocean/spectrum.hpp"

int main() {
  const auto spectrum = ocean::FrequencySpectrum::make(
      {.model = ocean::SpectrumModel::pierson_moskowitz, .wind_speed_mps = 15.0});
  if (!spectrum.ok()) return 1;
  const double hs = spectrum.value().hs_m();
  const double expected = 4.0 * std::sqrt(0.0081 / (4.0 * 0.74)) * 15.0 * 15.0 / 9.81;
  std::printf("Hs = %.6f m (closed form %.6f m)\n", hs, expected);
  if (!ocean::preset::builtin("storm").ok()) return 3;
  return std::abs(hs / expected - 1.0) < 1e-6 ? 0 : 2;
}
