// Time evolution of the packed spectrum and the field spectra packed two per complex plane.
//
// This work is based on:
//   - Tessendorf, J. (2001) Simulating Ocean Water, eqs. 43–44 (evolution), 29 (choppy
//     displacement), 37 (slopes).
//   - Aebi, VR Ocean, eqs. 24–30 (single-FMA evolution, i·k̂·h̃ displacement spectrum);
//     Vincevičius 2024, eq. 2.8, and Paleologue 2024 (slope spectrum i·k·h̃).
// Equations: docs/math.md (M.6.5), (M.7.2), (M.7.3).
#include <cmath>

#include "cpu_backend.hpp"

namespace ocean::cpu {

int plane_count(NormalMethod method) { return method == NormalMethod::analytic ? 4 : 2; }

void plane_factors(double kx, double kz, double lambda, int planes, std::complex<double>* f) {
  const double k = std::hypot(kx, kz);
  const double ux = k > 0.0 ? kx / k : 0.0;  // k̂
  const double uz = k > 0.0 ? kz / k : 0.0;
  using C = std::complex<double>;
  const C I(0.0, 1.0);
  // Field spectra as multiples of h̃ (M.7.2): D̃ = λ·i·k̂·h̃, slope = i·k·h̃,
  // ∂D̃x/∂x = −λ·kx·k̂x·h̃, ∂D̃z/∂z = −λ·kz·k̂z·h̃, ∂D̃x/∂z = −λ·kz·k̂x·h̃.
  const C h = 1.0, dx = lambda * I * ux, dz = lambda * I * uz;
  f[0] = h + I * dx;  // (h, Dx)
  if (planes == 2) {
    f[1] = dz;  // (Dz, unused)
    return;
  }
  const C hx = I * kx, hz = I * kz;
  const C dxx = -lambda * kx * ux, dzz = -lambda * kz * uz, dxz = -lambda * kz * ux;
  f[1] = dz + I * hx;    // (Dz, ∂h/∂x)
  f[2] = hz + I * dxx;   // (∂h/∂z, ∂Dx/∂x)
  f[3] = dzz + I * dxz;  // (∂Dz/∂z, ∂Dx/∂z)
}

void build_plane_factors(CascadeState& state, NormalMethod method, double choppiness) {
  const int n = state.resolution;
  const auto texels = static_cast<std::size_t>(n) * static_cast<std::size_t>(n);
  const double dk = 2.0 * kPi / state.patch_size_m;
  const int planes = plane_count(method);
  state.factor.assign(static_cast<std::size_t>(planes), std::vector<std::complex<float>>(texels));
  for (int row = 0; row < n; ++row) {
    for (int col = 0; col < n; ++col) {
      const std::size_t i = static_cast<std::size_t>(row * n + col);
      std::complex<double> f[4];
      plane_factors(dk * (col - n / 2), dk * (row - n / 2), choppiness, planes, f);
      for (int p = 0; p < planes; ++p) {
        state.factor[static_cast<std::size_t>(p)][i] = std::complex<float>(f[p]);
      }
    }
  }
}

void evolve(CascadeState& state, double time_s, double loop_period_s, TaskRunner& runner,
            CascadeState* dz_partner) {
  const int n = state.resolution;
  const EvolutionPhase phase_of(time_s, loop_period_s);  // exact after days (M.7.3)
  const std::size_t planes = state.factor.size();
  runner.parallel_for(
      static_cast<std::size_t>(n), 8, [&](std::size_t row_begin, std::size_t row_end) {
        for (std::size_t i = row_begin * static_cast<std::size_t>(n);
             i < row_end * static_cast<std::size_t>(n); ++i) {
          const double phase = phase_of(state.spectrum.omega[i]);
          const float c = static_cast<float>(std::cos(phase));
          const float s = static_cast<float>(std::sin(phase));
          const auto& p = state.spectrum.packed[i];
          const std::complex<float> h(p[0] * c + p[2] * s, p[1] * c + p[3] * s);  // (M.6.5)
          for (std::size_t q = 0; q < planes; ++q) {
            const std::complex<float> v = state.factor[q][i] * h;
            if (q == 1 && dz_partner != nullptr) {  // i·D̃z into the partner's plane 1
              dz_partner->plane_re[1][i] -= v.imag();
              dz_partner->plane_im[1][i] += v.real();
              continue;
            }
            state.plane_re[q][i] = v.real();
            state.plane_im[q][i] = v.imag();
          }
        }
      });
}

}  // namespace ocean::cpu
