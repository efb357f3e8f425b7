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
// each row s of the table is one inverse FFT over m of A(θ)·(dθ/dm)·i·e^{i·k_s(m)·s}. Each row
// keeps the columns of its own wedge and fringe, w(s) = 0.45·s + 2·2πU²/g + L (the cusp line is at
// 0.354·s), and its transform's period M·h is at least 2·w(s) + w(0), which bounds the aliasing to
// the Airy tail outside the cusps; M doubles in bands of rows as the wedge widens. The three
// components travel in two transforms (the spectrum's even and odd parts), and a transform longer
// than the FFT module's largest is split into S = M/P transforms of P points (W.5, W.7).
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

// The inverse DFT of M = S·P points from S transforms of P points (the FFT module's largest
// is fft::kMaxSize): x[S·r + q] = Σ_{k<P} Y_q[k]·e^{2πi·k·r/P}, with
// Y_q[k] = e^{2πi·q·k/M}·Σ_{j<S} X[k + j·P]·e^{2πi·q·j/S}. The combination runs in double
// precision, the transforms in float. Two spectra at once: the table's three real components
// travel as h + i·D_s and D_ζ (W.5).
class LateralTransform {
 public:
  explicit LateralTransform(int m)
      : m_(m), p_(std::min(m, fft::kMaxSize)), s_(m / p_), plan_(make_plan(p_)) {
    const auto mm = static_cast<std::size_t>(m_), sm = static_cast<std::size_t>(s_);
    if (s_ > 1) {
      twiddle_.resize(mm);  // e^{2πi·t/M}
      for (std::size_t t = 0; t < mm; ++t)
        twiddle_[t] = std::polar(1.0, 2.0 * kPi * static_cast<double>(t) / m_);
      roots_.resize(sm * sm);  // e^{2πi·q·j/S}
      for (std::size_t q = 0; q < sm; ++q)
        for (std::size_t j = 0; j < sm; ++j)
          roots_[q * sm + j] = twiddle_[(q * j % sm) * (mm / sm)];
    }
    re_.resize(2 * mm);  // Y_q of spectrum c at [(q·2 + c)·P, …)
    im_.resize(2 * mm);
    for (auto& x : spectra_) x.resize(mm);
  }
  /// The two spectra to fill, each M long.
  std::array<std::vector<std::complex<double>>, 2>& spectra() { return spectra_; }
  /// Transforms them and writes, times `scale`, Re and Im of the first and Re of the second at
  /// columns [0, cols) as out[3·col + 0, 1, 2].
  void transform(int cols, double scale, float* out) {
    const auto p = static_cast<std::size_t>(p_), sm = static_cast<std::size_t>(s_);
    for (std::size_t c = 0; c < 2; ++c) {
      const std::complex<double>* x = spectra_[c].data();
      if (sm == 1) {
        for (std::size_t k = 0; k < p; ++k) {
          re_[c * p + k] = static_cast<float>(x[k].real());
          im_[c * p + k] = static_cast<float>(x[k].imag());
        }
        continue;
      }
      for (std::size_t q = 0; q < sm; ++q) {
        const std::complex<double>* root = roots_.data() + q * sm;
        float* re = re_.data() + (q * 2 + c) * p;
        float* im = im_.data() + (q * 2 + c) * p;
        for (std::size_t k = 0; k < p; ++k) {
          std::complex<double> y = x[k];
          for (std::size_t j = 1; j < sm; ++j) y += x[k + j * p] * root[j];
          y *= twiddle_[q * k];  // q·k < S·P = M
          re[k] = static_cast<float>(y.real());
          im[k] = static_cast<float>(y.imag());
        }
      }
    }
    for (std::size_t q = 0; q < sm; ++q) {
      float* re = re_.data() + q * 2 * p;
      float* im = im_.data() + q * 2 * p;
      const std::array<fft::SplitComplex, 2> signals{{{re, im}, {re + p, im + p}}};
      plan_.inverse(signals);
      for (std::size_t r = 0; r < p; ++r) {
        const std::size_t col = sm * r + q;
        if (col >= static_cast<std::size_t>(cols)) break;
        out[3 * col] = static_cast<float>(scale * re[r]);
        out[3 * col + 1] = static_cast<float>(scale * im[r]);
        out[3 * col + 2] = static_cast<float>(scale * re[p + r]);
      }
    }
  }

 private:
  static fft::Plan1D make_plan(int p) {
    Result<fft::Plan1D> plan = fft::Plan1D::make(p);
    assert(plan.ok());
    return std::move(plan).value();
  }
  int m_, p_, s_;
  fft::Plan1D plan_;
  std::vector<std::complex<double>> twiddle_, roots_;
  std::array<std::vector<std::complex<double>>, 2> spectra_;
  std::vector<float> re_, im_;
};

}  // namespace

double KelvinTable::transverse_wavelength_m() const {
  return 2.0 * kPi * spec_.speed_mps * spec_.speed_mps / spec_.gravity_mps2;
}

KelvinTable KelvinTable::make(const KelvinTableSpec& spec) {
  KelvinTable t;
  t.spec_ = spec;
  const double wavelength = t.transverse_wavelength_m();
  // A row's half width: the cusp line (0.354·s) plus room for the Airy tail and the near field;
  // its transform's period is at least twice that.
  const double fringe = 2.0 * wavelength + spec.hull_length_m;
  const auto width_at = [&](int row, double h) {
    return static_cast<std::size_t>(std::ceil((0.45 * row * h + fringe) / h)) + 2;
  };
  const auto lateral_at = [&](int row, double h) {
    return next_power_of_two(static_cast<int>(2 * width_at(row, h) + width_at(0, h)));
  };
  double h = spec.spacing_m;
  for (;; h *= 1.25) {
    // Far too long or wide, before counting in integers.
    if (std::ceil(spec.length_m / h) >= static_cast<double>(kMaxKelvinTableCells) ||
        (0.45 * spec.length_m + fringe) / h >= kMaxKelvinLateral)
      continue;
    t.rows_ = static_cast<int>(std::ceil(spec.length_m / h)) + 1;
    const int widest = lateral_at(t.rows_ - 1, h);
    t.row_start_.assign(static_cast<std::size_t>(t.rows_) + 1, 0);
    for (int row = 0; row < t.rows_; ++row) {
      const auto r = static_cast<std::size_t>(row);
      t.row_start_[r + 1] = t.row_start_[r] + width_at(row, h);
    }
    if (widest <= kMaxKelvinLateral && t.row_start_.back() <= kMaxKelvinTableCells) break;
  }
  t.spacing_m_ = h;
  const double k0 = 2.0 * kPi / wavelength;
  t.unresolved_ = k0 >= 2.0 * kPi / (3.0 * h);
  t.values_.assign(3 * t.row_start_.back(), 0.0f);
  if (t.unresolved_) return t;

  const double ramp_m = 0.5 * spec.hull_length_m;
  double peak = 0.0;
  // Rows in bands of one transform size, which doubles as the wedge widens.
  for (int first = 0; first < t.rows_;) {
    const int m_count = lateral_at(first, h);
    int end = first;
    while (end < t.rows_ && lateral_at(end, h) == m_count) ++end;
    const std::vector<Mode> mode = modes(spec, h, m_count);
    LateralTransform lateral(m_count);
    auto& [packed, odd] = lateral.spectra();
    const auto m = static_cast<std::size_t>(m_count);
    // e^{i·k_s·s} of each mode, turned by e^{i·k_s·h} from one row to the next: the rotation's
    // rounding grows by about 1e-16 a row, far below the table's float precision.
    std::vector<std::complex<double>> phase(m), turn(m);
    for (std::size_t j = 0; j < m; ++j) {
      phase[j] = std::polar(1.0, mode[j].k_s * first * h);
      turn[j] = std::polar(1.0, mode[j].k_s * h);
    }
    for (int row = first; row < end; ++row) {
      const double s = row * h;
      for (std::size_t j = 0; j < m; ++j) {
        const Mode& q = mode[j];
        const double c = phase[j].real(), sn = phase[j].imag();
        phase[j] *= turn[j];
        // h̃ = w·i·e^{iψ} (W.5); D̃ = i·k̂·h̃ = −w·k̂·e^{iψ} (W.6). Modes ±m share w, k_s and
        // cosθ and have opposite sinθ, so the real parts of the three transforms are those of
        // the spectra's even parts −w·sinψ and −w·cosθ·cosψ and odd part −i·w·sinθ·sinψ:
        // h + i·D_s from one transform, D_ζ from another.
        packed[j] = {-q.weight * sn, -q.weight * q.cos_theta * c};
        odd[j] = {0.0, -q.weight * q.sin_theta * sn};
      }
      // The wave part starts at the object: ramp it in over half a hull length, and fade it
      // out over the table's last fade_m so that it ends without a step (W.7).
      const double window = smoothstep(s / ramp_m) * smoothstep((spec.length_m - s) / spec.fade_m);
      const auto r = static_cast<std::size_t>(row);
      const auto cols = static_cast<int>(t.row_start_[r + 1] - t.row_start_[r]);
      float* out = t.values_.data() + 3 * t.row_start_[r];
      lateral.transform(cols, window, out);
      for (int col = 0; col < cols; ++col)
        peak =
            std::max(peak, std::abs(static_cast<double>(out[3 * static_cast<std::size_t>(col)])));
    }
    first = end;
  }
  t.raw_peak_ = peak;
  if (peak > 0.0) {
    const auto scale = static_cast<float>(1.0 / peak);
    for (float& v : t.values_) v *= scale;
  }
  return t;
}

double KelvinTable::pattern_energy(const KelvinTableSpec& spec) {
  // (W.24) A(θ) of W.4 with k = k0·sec²θ; A² cos³θ falls as cos⁷θ towards θ = ±π/2. Midpoints
  // over [0, π/2), doubled (A is even in θ).
  const double k0 = spec.gravity_mps2 / (spec.speed_mps * spec.speed_mps);
  const double a = std::numbers::sqrt2 * spec.hull_length_m / (2.0 * kPi);
  const double b2 = kWakePressureAspect * kWakePressureAspect;
  constexpr int kSteps = 20000;
  const double dtheta = 0.5 * kPi / kSteps;
  double sum = 0.0;
  for (int i = 0; i < kSteps; ++i) {
    const double theta = (i + 0.5) * dtheta;
    const double c = std::cos(theta), sn = std::sin(theta);
    const double ka = k0 * a / (c * c);
    const double amplitude = ka * ka / std::pow(1.0 + ka * ka * (c * c + b2 * sn * sn), 1.5);
    sum += amplitude * amplitude * c * c * c * dtheta;
  }
  return 2.0 * sum;
}

std::array<double, 3> KelvinTable::sample(double s, double zeta) const {
  const double u = s / spacing_m_, v = std::abs(zeta) / spacing_m_;
  if (!(u >= 0.0 && v >= 0.0 && u < rows_ - 1)) return {0.0, 0.0, 0.0};
  const auto r0 = static_cast<std::size_t>(u);
  const std::size_t top_row = row_start_[r0], bottom_row = row_start_[r0 + 1];
  // The narrower row (the nearer one) bounds both: rows widen with s.
  if (!(v < static_cast<double>(bottom_row - top_row - 1))) return {0.0, 0.0, 0.0};
  const auto c0 = static_cast<std::size_t>(v);
  const double fr = u - static_cast<double>(r0), fc = v - static_cast<double>(c0);
  std::array<double, 3> out{};
  for (std::size_t k = 0; k < 3; ++k) {
    const float* p = values_.data() + 3 * (top_row + c0) + k;
    const float* q = values_.data() + 3 * (bottom_row + c0) + k;
    const double top = p[0] * (1.0 - fc) + p[3] * fc;
    const double bottom = q[0] * (1.0 - fc) + q[3] * fc;
    out[k] = top * (1.0 - fr) + bottom * fr;
  }
  if (zeta < 0.0) out[2] = -out[2];  // D_ζ is odd in ζ, h and D_s even
  return out;
}

}  // namespace ocean::waves::detail
