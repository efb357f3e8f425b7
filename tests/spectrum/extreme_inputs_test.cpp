// Every public evaluation of the spectrum module at extreme but valid inputs: frequencies and
// wavenumbers over all decades of double precision, denormals, depths from 1e-100 m to
// infinity. Results must be finite, and spectra must reach exactly 0 through the denormals
// where the physics says 0, never by way of inf·0 or 0/0.
#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <string>
#include <vector>

#include "ocean/spectrum.hpp"

namespace {

using ocean::DepthFactor;
using ocean::FrequencySpectrum;
using ocean::FrequencySpectrumParams;
using ocean::SpectrumModel;

// ω from the smallest denormal to the largest double: every decade, plus both ends.
std::vector<double> all_decades() {
  std::vector<double> v{DBL_TRUE_MIN, 1e-320, DBL_MIN};
  for (int e = -307; e <= 308; ++e) v.push_back(std::pow(10.0, e));
  v.push_back(DBL_MAX);
  return v;
}

struct Named {
  std::string name;
  FrequencySpectrumParams params;
};

std::vector<Named> spectra() {
  std::vector<Named> v{
      {"pm wind", {.model = SpectrumModel::pierson_moskowitz, .wind_speed_mps = 15.0}},
      {"pm hs/tp",
       {.model = SpectrumModel::pierson_moskowitz,
        .significant_wave_height_m = 50.0,
        .peak_period_s = 1e-3}},
      {"jonswap hs/tp",
       {.model = SpectrumModel::jonswap,
        .significant_wave_height_m = 1e-6,
        .peak_period_s = 100.0,
        .gamma = 20.0}},
      {"jonswap wind",
       {.model = SpectrumModel::jonswap,
        .wind_speed_mps = 100.0,
        .fetch_m = 1e8,
        .gravity_mps2 = 0.1}},
      {"jonswap calm",
       {.model = SpectrumModel::jonswap,
        .wind_speed_mps = 1e-3,
        .fetch_m = 1.0,
        .gravity_mps2 = 100.0}},
      {"phillips",
       {.model = SpectrumModel::phillips,
        .wind_speed_mps = 100.0,
        .gravity_mps2 = 0.1,
        .phillips_amplitude = 1e6}},
      {"phillips cutoff",
       {.model = SpectrumModel::phillips, .wind_speed_mps = 10.0, .small_wave_cutoff_m = 0.5}},
  };
  for (double depth : {1e-100, 1e-3, 10.0, 1e300}) {
    for (DepthFactor factor : {DepthFactor::exact, DepthFactor::thompson_vincent}) {
      v.push_back({"tma h = " + ocean::format_number(depth),
                   {.model = SpectrumModel::tma,
                    .wind_speed_mps = 20.0,
                    .fetch_m = 1e5,
                    .depth_m = depth,
                    .depth_factor = factor}});
    }
  }
  return v;
}

TEST(ExtremeInputs, EverySpectrumIsFiniteAtEveryFrequency) {
  for (const Named& n : spectra()) {
    const auto s = FrequencySpectrum::make(n.params);
    ASSERT_TRUE(s.ok()) << n.name << ": " << s.status().message();
    for (double omega : all_decades()) {
      const double v = s.value()(omega);
      EXPECT_TRUE(std::isfinite(v) && v >= 0.0) << n.name << ": S(" << omega << ") = " << v;
    }
    // Far from the peak the spectrum is 0: e^(−β(ωp/ω)⁴) below it, an ω⁻⁵ tail above it.
    for (double omega : {DBL_TRUE_MIN, 1e-300, 1e-100, 1e100, 1e300, DBL_MAX}) {
      EXPECT_EQ(s.value()(omega), 0.0) << n.name << ": S(" << omega << ")";
    }
  }
}

// Above the peak every model falls as ω⁻⁵ (M.3.1, M.3.3, M.3.7, M.3.11 without cutoff), TMA
// as ω⁻⁵·Φ (M.3.9): S(2ω)/S(ω) = Φ(2ω)/(32·Φ(ω)) as long as S(2ω) is a normal number, out to
// where it underflows.
TEST(ExtremeInputs, HighFrequencyTailIsOmegaToTheMinusFiveUntilItUnderflows) {
  for (const Named& n : spectra()) {
    if (n.name == "phillips cutoff") continue;
    const FrequencySpectrum s = FrequencySpectrum::make(n.params).value();
    const auto phi = [&](double omega) {
      const FrequencySpectrumParams& p = n.params;
      return p.model == SpectrumModel::tma
                 ? ocean::tma_depth_factor(omega, p.depth_m, p.gravity_mps2, p.depth_factor)
                 : 1.0;
    };
    int normal_points = 0;
    for (double omega = 1e3 * s.peak_omega(); omega < 1e300; omega *= 2.0) {
      const double next = s(2.0 * omega);
      if (!(next >= DBL_MIN)) break;
      ++normal_points;
      const double expected = phi(2.0 * omega) / (32.0 * phi(omega));
      EXPECT_NEAR(next / s(omega), expected, 1e-10 * expected) << n.name << " at w = " << omega;
    }
    EXPECT_GT(normal_points, 100) << n.name;
  }
}

// Below the peak, S reaches 0 through ever smaller values: the last value before the first 0,
// stepping ω down by 1 %, is below 1e-290 (a jump to 0 from a normal number is an overflow).
TEST(ExtremeInputs, LowFrequencySideReachesZeroThroughTheDenormals) {
  for (const Named& n : spectra()) {
    const FrequencySpectrum s = FrequencySpectrum::make(n.params).value();
    double previous = s(s.peak_omega());
    for (double omega = s.peak_omega(); omega > 1e-300; omega *= 0.99) {
      const double v = s(omega);
      if (v == 0.0) {
        EXPECT_LT(previous, 1e-290) << n.name << " at w = " << omega;
        break;
      }
      previous = v;
    }
  }
}

TEST(ExtremeInputs, DepthFactorIsBetweenZeroAndOneEverywhere) {
  for (double depth : {1e-100, 1e-10, 1.0, 1e10, 1e100, 1e300, ocean::kInfiniteDepth}) {
    for (DepthFactor factor : {DepthFactor::exact, DepthFactor::thompson_vincent}) {
      double previous = 0.0;
      for (double omega : all_decades()) {
        const double phi = ocean::tma_depth_factor(omega, depth, 9.81, factor);
        ASSERT_TRUE(phi >= previous && phi <= 1.0) << "h = " << depth << ", w = " << omega;
        previous = phi;
      }
      EXPECT_EQ(ocean::tma_depth_factor(1e300, depth, 9.81, factor), 1.0);
    }
  }
  // Shallow limit Φ = ωh²/2 (M.3.9) where ωh is below the dispersion domain, and deep limit 1.
  const double omega_h = 1e-120;
  EXPECT_DOUBLE_EQ(
      ocean::tma_depth_factor(omega_h * std::sqrt(9.81), 1.0, 9.81, DepthFactor::exact),
      0.5 * omega_h * omega_h);
  EXPECT_EQ(ocean::tma_depth_factor(1e-300, 1e-100, 9.81, DepthFactor::exact), 0.0);
}

// Γ(s+2)/Γ(s+3/2) = (s+1)/(s+½)·Γ(s+1)/Γ(s+½) exactly, and Γ(s+1)/Γ(s+½) → √s·(1 + 1/(8s)).
TEST(ExtremeInputs, SpreadingNormalisersHoldForEveryExponent) {
  for (double s = 1e-3; s < 1e15; s *= 3.7) {
    const double ratio = ocean::cos2s_normalization(s + 1.0) / ocean::cos2s_normalization(s);
    EXPECT_NEAR(ratio, (s + 1.0) / (s + 0.5), 1e-13) << "s = " << s;
  }
  for (double s : {1e6, 1e20, 1e100, 1e300, DBL_MAX}) {
    const double limit = std::sqrt(s) * (1.0 + 1.0 / (8.0 * s)) / (2.0 * std::sqrt(ocean::kPi));
    EXPECT_NEAR(ocean::cos2s_normalization(s), limit, 1e-13 * limit) << "s = " << s;
    // ∫|cos θ|^s dθ over the front half ~ √(2π/s).
    const double integral = ocean::power_cosine_integral(s, 0.0);
    EXPECT_NEAR(integral, std::sqrt(2.0 * ocean::kPi / s), 1e-6 * integral) << "s = " << s;
  }
}

TEST(ExtremeInputs, WaveVectorSpectrumIsFiniteForEveryWaveVector) {
  ocean::SeaStateParams p;
  p.wind_sea = {
      .spectrum = {.model = SpectrumModel::jonswap, .wind_speed_mps = 12.0, .fetch_m = 5e4},
      .spreading = {.model = ocean::SpreadingModel::donelan_banner}};
  p.dispersion.capillarity_m3ps2 = ocean::kSeaWaterCapillarity;
  p.dispersion.depth_m = 1e-3;
  const ocean::SeaState sea = ocean::SeaState::make(p).value();
  for (double k : all_decades()) {
    for (double kz : {0.0, k, -k}) {
      const double f = sea.wave_vector_spectrum(k, kz);
      EXPECT_TRUE(std::isfinite(f) && f >= 0.0) << "k = (" << k << ", " << kz << ")";
    }
  }
  EXPECT_EQ(sea.wave_vector_spectrum(1e-300, 0.0), 0.0);
  EXPECT_EQ(sea.wave_vector_spectrum(DBL_MAX, DBL_MAX), 0.0);
}

TEST(ExtremeInputs, VrOceanPowerIsFiniteForEveryWaveVector) {
  const ocean::VrOceanPhillipsParams p{.wind_speed_mps = 30.0, .alpha = 0.3};
  const ocean::SpectrumGrid grid{.resolution = 256, .patch_size_m = 500.0};
  for (double k : all_decades()) {
    const double power = ocean::vr_ocean_phillips_power(k, -k, p, grid);
    EXPECT_TRUE(std::isfinite(power) && power >= 0.0) << "k = " << k;
  }
  EXPECT_EQ(ocean::vr_ocean_phillips_power(DBL_MAX, DBL_MAX, p, grid), 0.0);
}

// The harmonic j = ω'·T/2π stays an exact integer far beyond the range of long.
TEST(ExtremeInputs, EvolutionRateIsTheHarmonicForHugeFrequencies) {
  const double period = 1e6;
  for (double omega : {1.0, 1e10, 1e14, 1e20}) {
    const double j = std::floor(omega * period / (2.0 * ocean::kPi));
    const double rate = ocean::EvolutionPhase::rate(ocean::quantize_omega(omega, period), period);
    EXPECT_NEAR(rate, j, 4e-15 * j) << "w = " << omega;
  }
}

TEST(ExtremeInputs, ParametersThatWouldOverflowAreRejected) {
  const auto amplitude = FrequencySpectrum::make(
      {.model = SpectrumModel::phillips, .wind_speed_mps = 10.0, .phillips_amplitude = 1e300});
  EXPECT_EQ(amplitude.status().message(),
            "phillips_amplitude = 1e+300 is out of range: must be in (0, 1e+06]");
  const auto depth = FrequencySpectrum::make(
      {.model = SpectrumModel::tma, .wind_speed_mps = 10.0, .fetch_m = 1e4, .depth_m = 1e-300});
  EXPECT_EQ(depth.status().message(),
            "depth_m = 1e-300 is out of range: must be in [1e-100, inf] (inf for deep water)");
}

}  // namespace
