// src/waves/kelvin_table.cpp — the steady ship-wave pattern of a moving pressure disturbance,
// evaluated once per (U, L) on a table in the object's frame.
//
// This work is based on:
//   Havelock, T. H. (1908), "The propagation of groups of waves in dispersive media, with
//     application to waves on water produced by a travelling disturbance", Proc. R. Soc. A 81 —
//     the wave part of the linear steady solution as an integral over the wave angle θ (W.3).
//   Darmon, A., Benzaquen, M. & Raphaël, E. (2014), "Kelvin wake pattern at large Froude
//     numbers", J. Fluid Mech. 738, R3, eqs. 2.1–2.5 — the same solution from the Fourier
//     transform of the pressure, ζ̂(k) = −k·p̂(k)/ρ / (gk − (k·U)² + 2iεk·U) (W.1).
//   Rabaud, M. & Moisy, F. (2013), "Ship wakes: Kelvin or Mach angle?", Phys. Rev. Lett. 110,
//     214503 — the finite size of the disturbance narrows the wake at Fr = U/√(gL) ≳ 0.5 (W.11).
//   Tessendorf, J. (2001), "Simulating Ocean Water", eq. 29 — horizontal displacement −i·k̂ (W.6,
//     with this project's sign, docs/math.md M.7.2).
//
// Evaluation (W.5): with u = tanθ the lateral wavenumber m = k0·u·√(1+u²) is monotonic in θ, so
// each row s of the table is one inverse FFT over m of A(θ)·(dθ/dm)·i·e^{i·k_s(m)·s}; the FFT
// period M·h must exceed twice the wake's half width (0.354·s for s within the table), which
// bounds the aliasing to the Airy tail outside the cusps.
#include "kelvin_table.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <complex>
#include <numbers>

#include "ocean/fft.hpp"
#include "ocean/waves.hpp"

namespace ocean::waves::detail {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr int kMaxRows = 4096;              // bounds the table to ~100 MB at N = 4096
constexpr int kMaxFftSize = fft::kMaxSize;  // the lateral transform

double smoothstep(double t) {
  t = std::clamp(t, 0.0, 1.0);
  return t * t * (3.0 - 2.0 * t);
}

int next_power_of_two(int n) {
  int p = 16;
  while (p < n) p *= 2;
  return p;
}

// One lateral wavenumber m_j of the row transform and what (W.5) needs of it.
struct Mode {
  double weight = 0.0;  // A(k)·taper(k)·(dθ/dm)·Δm, A of (W.4)
  double k_s = 0.0;     // wavenumber along s: k0·√(1+u²)
  double cos_theta = 1.0, sin_theta = 0.0;
};

std::vector<Mode> modes(const KelvinTableSpec& spec, double h, int m_count) {
  const double k0 = spec.gravity_mps2 / (spec.speed_mps * spec.speed_mps);  // (W.2)
  const double a = std::numbers::sqrt2 * spec.hull_length_m / (2.0 * kPi);  // (W.4)
  const double dm = 2.0 * kPi / (m_count * h);
  const double k_cut = 2.0 * kPi / (3.0 * h);  // 3 cells per wavelength at the end of the taper
  std::vector<Mode> out(static_cast<std::size_t>(m_count));
  for (int j = 0; j < m_count; ++j) {
    const int signed_j = j < m_count / 2 ? j : j - m_count;
    const double mu = signed_j * dm / k0;
    // u² from u²(1 + u²) = μ², in the form that keeps its digits for small μ.
    const double u2 = 2.0 * mu * mu / (std::sqrt(1.0 + 4.0 * mu * mu) + 1.0);
    const double u = std::copysign(std::sqrt(u2), mu);
    const double sec = std::sqrt(1.0 + u2);
    const double k = k0 * (1.0 + u2);
    const double ka2 = k * a * k * a;
    // a²·(k_s² + β²·m²) = (k·a)²·(cos²θ + β²·sin²θ), cos²θ = 1/(1 + u²)
    const double kq2 = ka2 * (1.0 + kWakePressureAspect * kWakePressureAspect * u2) / (1.0 + u2);
    const double amplitude = ka2 / std::pow(1.0 + kq2, 1.5);  // (k·a)²·p̂(k)/p̂(0)  (W.4)
    const double taper = k <= 0.5 * k_cut ? 1.0
                         : k >= k_cut     ? 0.0
                                          : 0.5 + 0.5 * std::cos(kPi * (2.0 * k / k_cut - 1.0));
    const double dtheta_dm = 1.0 / (k0 * sec * (1.0 + 2.0 * u2));
    out[static_cast<std::size_t>(j)] = {.weight = amplitude * taper * dtheta_dm * dm,
                                        .k_s = k0 * sec,
                                        .cos_theta = 1.0 / sec,
                                        .sin_theta = u / sec};
  }
  return out;
}

}  // namespace

double KelvinTable::transverse_wavelength_m() const {
  return 2.0 * kPi * spec_.speed_mps * spec_.speed_mps / spec_.gravity_mps2;
}

KelvinTable KelvinTable::make(const KelvinTableSpec& spec) {
  KelvinTable t;
  t.spec_ = spec;
  const double wavelength = t.transverse_wavelength_m();
  // Half width: the cusp line (0.354·s) plus room for the Airy tail and the near field.
  const double half_width = 0.45 * spec.length_m + 2.0 * wavelength + spec.hull_length_m;
  double h = spec.spacing_m;
  int m_count = 0;
  for (;; h *= 1.25) {
    t.rows_ = static_cast<int>(std::ceil(spec.length_m / h)) + 1;
    t.cols_ = static_cast<int>(std::ceil(half_width / h)) + 2;
    m_count = next_power_of_two(2 * t.cols_);
    if (t.rows_ <= kMaxRows && m_count <= kMaxFftSize) break;
  }
  t.spacing_m_ = h;
  const double k0 = 2.0 * kPi / wavelength;
  t.unresolved_ = k0 >= 2.0 * kPi / (3.0 * h);
  const auto cells = static_cast<std::size_t>(t.rows_) * static_cast<std::size_t>(t.cols_);
  t.values_.assign(3 * cells, 0.0f);
  if (t.unresolved_) return t;

  const std::vector<Mode> mode = modes(spec, h, m_count);
  Result<fft::Plan1D> plan = fft::Plan1D::make(m_count);
  assert(plan.ok());
  const auto m = static_cast<std::size_t>(m_count);
  std::vector<float> re(3 * m), im(3 * m);
  const std::array<fft::SplitComplex, 3> signals{{{re.data(), im.data()},
                                                  {re.data() + m, im.data() + m},
                                                  {re.data() + 2 * m, im.data() + 2 * m}}};
  const double ramp_m = 0.5 * spec.hull_length_m, fade_m = 0.1 * spec.length_m;
  // e^{i·k_s·s} of each mode, turned by e^{i·k_s·h} from one row to the next: the rotation's
  // rounding grows by about 1e-16 a row, far below the table's float precision.
  std::vector<std::complex<double>> phase(m, 1.0), turn(m);
  for (std::size_t j = 0; j < m; ++j) turn[j] = std::polar(1.0, mode[j].k_s * h);
  double peak = 0.0;
  for (int row = 0; row < t.rows_; ++row) {
    const double s = row * h;
    for (std::size_t j = 0; j < m; ++j) {
      const Mode& q = mode[j];
      const double c = phase[j].real(), sn = phase[j].imag();
      phase[j] *= turn[j];
      // h̃ = w·i·e^{iψ} (W.5); D̃ = i·k̂·h̃ = −w·k̂·e^{iψ} (W.6).
      re[j] = static_cast<float>(-q.weight * sn);
      im[j] = static_cast<float>(q.weight * c);
      re[m + j] = static_cast<float>(-q.weight * q.cos_theta * c);
      im[m + j] = static_cast<float>(-q.weight * q.cos_theta * sn);
      re[2 * m + j] = static_cast<float>(-q.weight * q.sin_theta * c);
      im[2 * m + j] = static_cast<float>(-q.weight * q.sin_theta * sn);
    }
    plan.value().inverse(signals);
    // The wave part starts at the object: ramp it in over half a hull length, and fade it out
    // over the last tenth of the table so that it ends without a step (W.7).
    const double window = smoothstep(s / ramp_m) * smoothstep((spec.length_m - s) / fade_m);
    float* out =
        t.values_.data() + 3 * static_cast<std::size_t>(row) * static_cast<std::size_t>(t.cols_);
    for (int col = 0; col < t.cols_; ++col) {
      const auto c = static_cast<std::size_t>(col);
      for (std::size_t k = 0; k < 3; ++k)
        out[3 * c + k] = static_cast<float>(window * re[k * m + c]);
      peak = std::max(peak, std::abs(static_cast<double>(out[3 * c])));
    }
  }
  if (peak > 0.0) {
    const auto scale = static_cast<float>(1.0 / peak);
    for (float& v : t.values_) v *= scale;
  }
  return t;
}

std::array<double, 3> KelvinTable::sample(double s, double zeta) const {
  const double u = s / spacing_m_, v = std::abs(zeta) / spacing_m_;
  if (!(u >= 0.0 && v >= 0.0 && u < rows_ - 1 && v < cols_ - 1)) return {0.0, 0.0, 0.0};
  const double r0 = std::floor(u), c0 = std::floor(v);
  const double fr = u - r0, fc = v - c0;
  const auto base = 3 * (static_cast<std::size_t>(r0) * static_cast<std::size_t>(cols_) +
                         static_cast<std::size_t>(c0));
  const std::size_t down = 3 * static_cast<std::size_t>(cols_);
  std::array<double, 3> out{};
  for (std::size_t k = 0; k < 3; ++k) {
    const float* p = values_.data() + base + k;
    const double top = p[0] * (1.0 - fc) + p[3] * fc;
    const double bottom = p[down] * (1.0 - fc) + p[down + 3] * fc;
    out[k] = top * (1.0 - fr) + bottom * fr;
  }
  if (zeta < 0.0) out[2] = -out[2];  // D_ζ is odd in ζ, h and D_s even
  return out;
}

}  // namespace ocean::waves::detail
