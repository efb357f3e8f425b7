// Deterministic Gaussian draws and h0(k): statistics, reproducibility, the variance convention
// (E[h²] = m0), Hermitian packing and the evolution direction.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <cstring>
#include <vector>

#include "ocean/spectrum.hpp"
#include "spectrum/test_util.hpp"

namespace {

using ocean::InitialSpectrum;
using ocean::SeaState;

SeaState jonswap_sea(double direction = 0.3) {
  ocean::SeaStateParams p;
  p.wind_sea = {
      .spectrum = {.model = ocean::SpectrumModel::jonswap, .wind_speed_mps = 10.0, .fetch_m = 1e5},
      .spreading = {.model = ocean::SpreadingModel::donelan_banner},
      .direction_rad = direction};
  return SeaState::make(p).value();
}

TEST(GaussianPair, IsDeterministicAndStandardNormal) {
  EXPECT_EQ(ocean::gaussian_pair(7, 12345), ocean::gaussian_pair(7, 12345));
  EXPECT_NE(ocean::gaussian_pair(7, 12345), ocean::gaussian_pair(8, 12345));
  EXPECT_NE(ocean::gaussian_pair(7, 12345), ocean::gaussian_pair(7, 12346));
  constexpr int kCount = 200000;
  double sum = 0, sum2 = 0, sum4 = 0, cross = 0;
  for (int i = 0; i < kCount; ++i) {
    const auto [a, b] = ocean::gaussian_pair(42, static_cast<std::uint64_t>(i));
    sum += a + b;
    sum2 += a * a + b * b;
    sum4 += a * a * a * a + b * b * b * b;
    cross += a * b;
  }
  const double n = 2.0 * kCount;
  EXPECT_NEAR(sum / n, 0.0, 5.0 / std::sqrt(n));
  EXPECT_NEAR(sum2 / n, 1.0, 5.0 * std::sqrt(2.0 / n));
  EXPECT_NEAR(sum4 / n, 3.0, 5.0 * std::sqrt(96.0 / n));  // kurtosis of a normal is 3
  EXPECT_NEAR(cross / kCount, 0.0, 5.0 / std::sqrt(kCount));
}

TEST(InitialSpectrum, IsBitIdenticalAcrossRuns) {
  const SeaState sea = jonswap_sea();
  const ocean::InitialSpectrumParams p{.grid = {.resolution = 64, .patch_size_m = 300.0},
                                       .seed = 9};
  const InitialSpectrum a = ocean::make_initial_spectrum(sea, p).value();
  const InitialSpectrum b = ocean::make_initial_spectrum(sea, p).value();
  ASSERT_EQ(a.packed.size(), 64u * 64u);
  EXPECT_EQ(std::memcmp(a.packed.data(), b.packed.data(), a.packed.size() * sizeof(a.packed[0])),
            0);
  EXPECT_EQ(std::memcmp(a.omega.data(), b.omega.data(), a.omega.size() * sizeof(float)), 0);
  const std::size_t dc = 32 * 64 + 32;
  EXPECT_EQ(a.h0[dc], std::complex<double>(0.0, 0.0));
  EXPECT_EQ(a.omega[dc], 0.0f);
}

// (M.6.2): E|h0(k)|² = F(k)·Δk²/2, so the realised variance Σ|h̃|² has mean Σ F·Δk², and that
// sum approaches m0 when the patch resolves the spectrum.
TEST(InitialSpectrum, VarianceConventionGivesM0) {
  const SeaState sea = jonswap_sea();
  const ocean::SpectrumGrid grid{.resolution = 128, .patch_size_m = 600.0};
  const double dk = 2.0 * ocean::kPi / grid.patch_size_m;
  std::vector<double> cell_variance;  // F(k)·Δk² per grid wave vector
  double grid_variance = 0.0;         // Σ F·Δk²
  for (int row = 0; row < grid.resolution; ++row) {
    for (int col = 0; col < grid.resolution; ++col) {
      // The Nyquist row and column (index 0) are not synthesised (M.6.3).
      const double f =
          row == 0 || col == 0 ? 0.0 : sea.wave_vector_spectrum(dk * (col - 64), dk * (row - 64));
      cell_variance.push_back(f * dk * dk);
      grid_variance += cell_variance.back();
    }
  }
  EXPECT_LT(ocean_test::relative_error(grid_variance, sea.variance_m2()), 0.03);
  constexpr int kSeeds = 48;
  double ratio_sum = 0.0;  // Σ |h0|²/(F·Δk²/2): each term has mean 1
  int ratio_count = 0;
  double realised = 0.0;
  for (int seed = 1; seed <= kSeeds; ++seed) {
    const InitialSpectrum h =
        ocean::make_initial_spectrum(sea, {.grid = grid, .seed = static_cast<std::uint64_t>(seed)})
            .value();
    double sum = 0.0;
    for (const auto& s : h.packed) sum += double(s[0]) * s[0] + double(s[1]) * s[1];  // |h̃(k,0)|²
    realised += sum / kSeeds;
    for (std::size_t i = 0; i < h.h0.size(); ++i) {
      if (cell_variance[i] < 1e-30) continue;
      ratio_sum += std::norm(h.h0[i]) / (0.5 * cell_variance[i]);
      ++ratio_count;
    }
  }
  EXPECT_NEAR(ratio_sum / ratio_count, 1.0, 5.0 / std::sqrt(double(ratio_count)));
  EXPECT_LT(ocean_test::relative_error(realised, grid_variance), 0.06);
}

// Aebi, VR Ocean, eqs. 18–24: the packed S' evolves as h0(k)·e^{−iωt} + h0*(−k)·e^{+iωt} (energy at
// k travels along +k), and h̃(−k, t) = h̃*(k, t) so the height field is real.
TEST(InitialSpectrum, PackedEvolutionMatchesDirectFormulaAndIsHermitian) {
  const SeaState sea = jonswap_sea();
  const int n = 32;
  const InitialSpectrum h = ocean::make_initial_spectrum(
                                sea, {.grid = {.resolution = n, .patch_size_m = 200.0}, .seed = 3})
                                .value();
  const auto evolve = [&](std::size_t i, double t) {
    const double phase = double(h.omega[i]) * t;
    const auto& s = h.packed[i];
    return std::complex<double>(s[0] * std::cos(phase) + s[2] * std::sin(phase),
                                s[1] * std::cos(phase) + s[3] * std::sin(phase));
  };
  for (double t : {0.0, 1.7, 55.0}) {
    for (int row = 0; row < n; ++row) {
      for (int col = 0; col < n; ++col) {
        const std::size_t i = static_cast<std::size_t>(row * n + col);
        const std::size_t j = static_cast<std::size_t>(((n - row) % n) * n + (n - col) % n);
        const double w = h.omega[i];
        const std::complex<double> direct =
            h.h0[i] * std::polar(1.0, -w * t) + std::conj(h.h0[j]) * std::polar(1.0, w * t);
        const std::complex<double> packed = evolve(i, t);
        const double scale = std::abs(h.h0[i]) + std::abs(h.h0[j]) + 1e-30;
        EXPECT_LT(std::abs(packed - direct), 1e-6 * scale);
        EXPECT_LT(std::abs(evolve(j, t) - std::conj(packed)), 1e-6 * scale);
      }
    }
  }
}

// Cascades split the spectrum into bands: complementary bands add up to the full spectrum
// exactly, wave vector by wave vector.
TEST(InitialSpectrum, BandsPartitionTheSpectrum) {
  const SeaState sea = jonswap_sea();
  const ocean::SpectrumGrid grid{.resolution = 64, .patch_size_m = 250.0};
  const double split = 0.6;  // rad/m
  const InitialSpectrum full = ocean::make_initial_spectrum(sea, {.grid = grid, .seed = 4}).value();
  const InitialSpectrum low =
      ocean::make_initial_spectrum(sea, {.grid = grid, .seed = 4, .k_max_radpm = split}).value();
  const InitialSpectrum high =
      ocean::make_initial_spectrum(sea, {.grid = grid, .seed = 4, .k_min_radpm = split}).value();
  int in_low = 0, in_high = 0;
  for (std::size_t i = 0; i < full.h0.size(); ++i) {
    EXPECT_EQ(low.h0[i] + high.h0[i], full.h0[i]);
    EXPECT_TRUE(low.h0[i] == 0.0 || high.h0[i] == 0.0);
    in_low += low.h0[i] != 0.0;
    in_high += high.h0[i] != 0.0;
  }
  EXPECT_GT(in_low, 100);
  EXPECT_GT(in_high, 100);
  EXPECT_FALSE(ocean::make_initial_spectrum(sea, {.k_min_radpm = 2.0, .k_max_radpm = 1.0}).ok());
}

TEST(InitialSpectrum, NyquistRowAndColumnAreEmpty) {
  const InitialSpectrum h = ocean::make_initial_spectrum(
                                jonswap_sea(), {.grid = {.resolution = 32, .patch_size_m = 20.0}})
                                .value();
  for (int i = 0; i < 32; ++i) {
    EXPECT_EQ(h.h0[static_cast<std::size_t>(i)], 0.0);       // row 0
    EXPECT_EQ(h.h0[static_cast<std::size_t>(i * 32)], 0.0);  // column 0
  }
}

TEST(InitialSpectrum, LoopPeriodQuantisesEveryFrequency) {
  const SeaState sea = jonswap_sea();
  const InitialSpectrum h =
      ocean::make_initial_spectrum(
          sea, {.grid = {.resolution = 32, .patch_size_m = 100.0}, .loop_period_s = 100.0})
          .value();
  const double omega0 = 2.0 * ocean::kPi / 100.0;
  for (float w : h.omega) {
    const double harmonics = double(w) / omega0;
    EXPECT_NEAR(harmonics, std::round(harmonics), 1e-4 * std::max(1.0, harmonics));
  }
}

TEST(InitialSpectrum, VrOceanConventionUsesSeedAmplitude) {
  ocean::SeaStateParams p;
  p.wind_sea = {.spectrum = {.model = ocean::SpectrumModel::phillips, .wind_speed_mps = 10.0},
                .spreading = {.model = ocean::SpreadingModel::power_cosine, .alpha = 0.8}};
  const SeaState sea = SeaState::make(p).value();
  const ocean::SpectrumGrid grid{.resolution = 32, .patch_size_m = 100.0};
  const InitialSpectrum h =
      ocean::make_initial_spectrum(
          sea, {.grid = grid, .seed = 5, .convention = ocean::AmplitudeConvention::vr_ocean})
          .value();
  const double dk = 2.0 * ocean::kPi / grid.patch_size_m;
  const std::size_t i = 20 * 32 + 21;
  const auto [xr, xi] = ocean::gaussian_pair(5, i);
  const double power =
      ocean::vr_ocean_phillips_power(dk * 5, dk * 4, {.wind_speed_mps = 10.0, .alpha = 0.8}, grid);
  EXPECT_NEAR(h.h0[i].real(), xr * std::sqrt(power / 2.0), 1e-12);
  EXPECT_NEAR(h.h0[i].imag(), xi * std::sqrt(power / 2.0), 1e-12);
  // Only defined for Aebi's Phillips + power-cosine.
  EXPECT_FALSE(
      ocean::make_initial_spectrum(
          jonswap_sea(), {.grid = grid, .convention = ocean::AmplitudeConvention::vr_ocean})
          .ok());
}

TEST(InitialSpectrum, RejectsBadGrids) {
  const SeaState sea = jonswap_sea();
  for (int n : {0, 8, 100, 8192}) {
    const auto r = ocean::make_initial_spectrum(sea, {.grid = {.resolution = n}});
    ASSERT_FALSE(r.ok());
    EXPECT_NE(r.status().message().find("resolution = " + std::to_string(n)), std::string::npos);
  }
  EXPECT_FALSE(ocean::make_initial_spectrum(sea, {.grid = {.patch_size_m = 0.0}}).ok());
  EXPECT_FALSE(ocean::make_initial_spectrum(sea, {.grid = {.patch_size_m = std::nan("")}}).ok());
  EXPECT_FALSE(ocean::make_initial_spectrum(sea, {.loop_period_s = -1.0}).ok());
}

}  // namespace
