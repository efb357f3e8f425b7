// Initial Fourier amplitudes h0(k) on the patch's wave-vector grid, the loop-quantised ω'(k) and
// the packed, pre-transformed layout of Aebi, VR Ocean, for single-FMA time evolution.
//
// This work is based on:
//   - Tessendorf, J. (2001) Simulating Ocean Water, eqs. 42–43 (h0 = ξ·√(P/2), h̃ = h0·e^{iωt} +
//     h0*(−k)·e^{−iωt}).
//   - Aebi, VR Ocean, §3.2.5–3.4 (Box–Muller, DC guard, eq. 16 quantisation, eqs. 18–24 packing).
// Amplitude convention and the direction of travel: docs/math.md §6 (M.6.2)–(M.6.5).
#include <bit>
#include <cmath>
#include <string>

#include "ocean/spectrum.hpp"

namespace ocean {

Status validate(const SpectrumGrid& grid) {
  const int n = grid.resolution;
  if (n < 16 || n > 4096 || !std::has_single_bit(static_cast<unsigned>(n))) {
    return invalid_argument("resolution = " + std::to_string(n) +
                            " is out of range: must be a power of two in [16, 4096]");
  }
  return require_in_range("patch_size_m", grid.patch_size_m, 1e-3, 1e7);
}

namespace {

Status validate_vr_ocean(const SeaState& sea) {
  const WaveSystem& w = sea.systems().front();
  if (sea.systems().size() != 1 || w.spectrum().params().model != SpectrumModel::phillips ||
      w.spreading().params().model != SpreadingModel::power_cosine) {
    return invalid_argument(
        "amplitude convention vr_ocean needs a single phillips wave system "
        "with power-cosine spreading (Aebi, VR Ocean, §3.2)");
  }
  return {};
}

// The standard deviation scale of h0 at every grid wave vector (E|h0|² = 2·amplitude², ξ has
// E|ξ|² = 2) and ω', after the checks every use needs; 0 at DC, on the Nyquist row and column and
// outside the band (M.6.3).
struct GridAmplitudes {
  std::vector<double> amplitude;
  std::vector<unsigned char> drawn;  // 1 where h0 = ξ·amplitude (0: h0 = 0 without a draw)
  std::vector<float> omega;
};

Result<GridAmplitudes> grid_amplitudes(const SeaState& sea, const InitialSpectrumParams& p) {
  if (Status s = validate(p.grid); !s.ok()) return s;
  if (Status s = require_in_range("loop_period_s", p.loop_period_s, 0.0, 1e6); !s.ok()) return s;
  if (!(p.k_min_radpm >= 0.0) || !(p.k_max_radpm > p.k_min_radpm)) {
    return invalid_argument("wavenumber band [" + format_number(p.k_min_radpm) + ", " +
                            format_number(p.k_max_radpm) +
                            ") is empty or negative: need 0 <= k_min < k_max");
  }
  if (p.convention == AmplitudeConvention::vr_ocean) {
    if (Status s = validate_vr_ocean(sea); !s.ok()) return s;
  }
  const int n = p.grid.resolution;
  const std::size_t count = static_cast<std::size_t>(n) * static_cast<std::size_t>(n);
  const double dk = 2.0 * kPi / p.grid.patch_size_m;
  GridAmplitudes out;
  out.amplitude.assign(count, 0.0);
  out.drawn.assign(count, 0);
  out.omega.resize(count);

  VrOceanPhillipsParams vr;
  if (p.convention == AmplitudeConvention::vr_ocean) {
    const WaveSystem& w = sea.systems().front();
    const FrequencySpectrumParams& sp = w.spectrum().params();
    vr = {.wind_speed_mps = sp.wind_speed_mps,
          .wind_direction_rad = w.direction_rad(),
          .alpha = w.spreading().params().alpha,
          .small_wave_cutoff_m = sp.small_wave_cutoff_m,
          .gravity_mps2 = sp.gravity_mps2};
  }
  const int half = n / 2;
  for (int row = 0; row < n; ++row) {
    for (int col = 0; col < n; ++col) {
      const std::size_t i = static_cast<std::size_t>(row) * static_cast<std::size_t>(n) +
                            static_cast<std::size_t>(col);
      const double kx = dk * (col - half);  // Aebi, VR Ocean, eq. 2
      const double kz = dk * (row - half);
      const double k = std::hypot(kx, kz);
      double omega = sea.dispersion().omega(k);
      if (p.loop_period_s > 0.0) omega = quantize_omega(omega, p.loop_period_s);  // (M.2.4)
      out.omega[i] = static_cast<float>(omega);
      // DC guard (Aebi, VR Ocean, eq. 14), Nyquist row/column and the band limits (M.6.3).
      const bool nyquist = row == 0 || col == 0;
      if ((col == half && row == half) || nyquist || k < p.k_min_radpm || k >= p.k_max_radpm) {
        if (col == half && row == half) out.omega[i] = 0.0f;
        continue;
      }
      out.drawn[i] = 1;
      if (p.convention == AmplitudeConvention::variance_preserving) {
        // E|h0|² = F·Δk²/2 with E|ξ|² = 2   (M.6.2)
        out.amplitude[i] = 0.5 * std::sqrt(sea.wave_vector_spectrum(kx, kz) * dk * dk);
      } else {
        out.amplitude[i] =
            std::sqrt(0.5 * vr_ocean_phillips_power(kx, kz, vr, p.grid));  // Aebi, VR Ocean, eq. 13
      }
    }
  }
  return out;
}

}  // namespace

Result<std::vector<double>> expected_wave_power(const SeaState& sea,
                                                const InitialSpectrumParams& p) {
  Result<GridAmplitudes> grid = grid_amplitudes(sea, p);
  if (!grid.ok()) return grid.status();
  std::vector<double> power = std::move(grid.value().amplitude);
  for (double& a : power) a = 4.0 * a * a;  // 2·E|h0|²: Σ over the grid is E[h²]
  return power;
}

Result<InitialSpectrum> make_initial_spectrum(const SeaState& sea, const InitialSpectrumParams& p) {
  Result<GridAmplitudes> grid = grid_amplitudes(sea, p);
  if (!grid.ok()) return grid.status();
  const int n = p.grid.resolution;
  const std::size_t count = static_cast<std::size_t>(n) * static_cast<std::size_t>(n);
  InitialSpectrum out;
  out.resolution = n;
  out.patch_size_m = p.grid.patch_size_m;
  out.h0.resize(count);
  out.omega = std::move(grid.value().omega);
  out.packed.resize(count);
  for (std::size_t i = 0; i < count; ++i) {
    const double amplitude = grid.value().amplitude[i];
    if (grid.value().drawn[i] == 0) {
      out.h0[i] = 0.0;
      continue;
    }
    const auto [xi_re, xi_im] = gaussian_pair(p.seed, i);
    out.h0[i] = {xi_re * amplitude, xi_im * amplitude};
  }
  // Pack (a, b) = h0(k), (c, d) = h0*(−k) and pre-transform   (M.6.5, Aebi, VR Ocean, eqs. 18–22).
  // −k of grid index (col, row) is ((N − col) mod N, (N − row) mod N).
  const unsigned mask = static_cast<unsigned>(n - 1);
  for (int row = 0; row < n; ++row) {
    for (int col = 0; col < n; ++col) {
      const std::size_t i = static_cast<std::size_t>(row * n + col);
      const std::size_t j = static_cast<std::size_t>(
          ((static_cast<unsigned>(n - row) & mask) * static_cast<unsigned>(n)) +
          (static_cast<unsigned>(n - col) & mask));
      const double a = out.h0[i].real();
      const double b = out.h0[i].imag();
      const double c = out.h0[j].real();
      const double d = -out.h0[j].imag();
      out.packed[i] = {static_cast<float>(a + c), static_cast<float>(b + d),
                       static_cast<float>(b - d), static_cast<float>(c - a)};
    }
  }
  return out;
}

}  // namespace ocean
