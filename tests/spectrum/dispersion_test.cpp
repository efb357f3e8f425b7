// Dispersion relation: published k(ω)/ω(k) values and exact identities.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "ocean/spectrum.hpp"

namespace {

using ocean::Dispersion;

Dispersion make(double depth, double capillarity = 0.0) {
  return Dispersion::make(
             {.gravity_mps2 = 9.81, .depth_m = depth, .capillarity_m3ps2 = capillarity})
      .value();
}

// WAFO (wafo-project/pywafo @c831ec8), src/wafo/wave_theory/tests/test_dispersion_relation.py
// lines 11–53, g = 9.81, assert_allclose rtol 1e-7.
TEST(Dispersion, WafoW2kDeepAndFiniteDepth) {
  const double omega[] = {1.0, 2.0, 3.0};
  const double k_deep[] = {0.1019368, 0.4077472, 0.91743119};
  const double k_20[] = {0.10503601, 0.40774726, 0.91743119};
  const Dispersion deep = make(ocean::kInfiniteDepth);
  const Dispersion h20 = make(20.0);
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(deep.wavenumber(omega[i]), k_deep[i], 1e-7 * k_deep[i]);
    EXPECT_NEAR(h20.wavenumber(omega[i]), k_20[i], 1e-7 * k_20[i]);
  }
  EXPECT_EQ(deep.wavenumber(0.0), 0.0);
}

TEST(Dispersion, WafoK2wDeepAndFiniteDepth) {
  const double k[] = {0.01, 0.21, 0.41};
  const double w_deep[] = {0.3132092, 1.43530485, 2.00551739};
  const double w_20[] = {0.13914927, 1.43498213, 2.00551724};
  const Dispersion deep = make(ocean::kInfiniteDepth);
  const Dispersion h20 = make(20.0);
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(deep.omega(k[i]), w_deep[i], 1e-7 * w_deep[i]);
    EXPECT_NEAR(h20.omega(k[i]), w_20[i], 1e-7 * w_20[i]);
  }
}

// MHKiT-Python @9fa9f9c, examples/data/wave/ValData1.json ("Data1": h = 10 m, "Data11":
// h = 50 m), used by mhkit/tests/wave/test_resource_metrics.py test_kfromw; consistent with
// g = 9.81 to < 1e-7.
TEST(Dispersion, MhkitValidationData) {
  struct Row {
    double depth, k, omega;
  };
  const Row rows[] = {{10, 1.0, 3.132092073927611},
                      {10, 0.16666666666666666, 1.23384124328053},
                      {10, 0.09090909090909091, 0.8017041035494386},
                      {10, 0.038461538461538464, 0.37197056880672064},
                      {10, 0.0196078431372549, 0.1929772694747361},
                      {10, 0.00684931506849315, 0.06778638137092065},
                      {50, 0.16666666666666666, 1.2786711125822066},
                      {50, 0.038461538461538464, 0.601269442355174},
                      {50, 0.00684931506849315, 0.14883407027691486}};
  for (const Row& r : rows) {
    const Dispersion d = make(r.depth);
    EXPECT_NEAR(d.wavenumber(r.omega), r.k, 2e-7 * r.k) << "h = " << r.depth;
    EXPECT_NEAR(d.omega(r.k), r.omega, 2e-7 * r.omega) << "h = " << r.depth;
  }
}

// USACE Coastal Engineering Manual EM 1110-2-1100 Part II-1, Example Problem II-1-1:
// T = 10 s in d = 3 m gives L = 53.2 m (three significant figures).
TEST(Dispersion, CoastalEngineeringManualExample) {
  const Dispersion d = make(3.0);
  const double wavelength = 2.0 * ocean::kPi / d.wavenumber(2.0 * ocean::kPi / 10.0);
  EXPECT_NEAR(wavelength, 53.2, 0.05);
}

TEST(Dispersion, InverseSatisfiesRelationEverywhere) {
  for (double depth : {0.05, 1.0, 10.0, 200.0, 5000.0, ocean::kInfiniteDepth}) {
    for (double cap : {0.0, ocean::kSeaWaterCapillarity}) {
      const Dispersion d = make(depth, cap);
      for (double omega = 1e-3; omega < 300.0; omega *= 1.37) {
        const double k = d.wavenumber(omega);
        const double t = std::isinf(depth) ? 1.0 : std::tanh(k * depth);
        const double residual = (9.81 * k + cap * k * k * k) * t - omega * omega;
        EXPECT_NEAR(residual, 0.0, 1e-12 * omega * omega) << "h=" << depth << " w=" << omega;
        EXPECT_NEAR(d.omega(k), omega, 1e-12 * omega);
      }
    }
  }
}

TEST(Dispersion, GroupVelocityIsDerivativeAndHasLimits) {
  const Dispersion d = make(15.0, ocean::kSeaWaterCapillarity);
  for (double k = 1e-3; k < 2000.0; k *= 1.9) {
    const double h = 1e-6 * k;
    const double numeric = (d.omega(k + h) - d.omega(k - h)) / (2.0 * h);
    EXPECT_NEAR(d.group_velocity(k), numeric, 1e-6 * numeric) << "k=" << k;
  }
  // Deep water: c_g = c/2. Shallow water: c_g → √(gh).
  const Dispersion deep = make(ocean::kInfiniteDepth);
  EXPECT_NEAR(deep.group_velocity(0.3), 0.5 * deep.omega(0.3) / 0.3, 1e-14);
  const Dispersion shallow = make(2.0);
  EXPECT_NEAR(shallow.group_velocity(1e-5), std::sqrt(9.81 * 2.0), 1e-6);
}

TEST(Dispersion, LoopQuantisationRepeatsAfterPeriod) {
  const double period = 200.0;
  const double omega0 = 2.0 * ocean::kPi / period;
  for (double omega = 0.01; omega < 20.0; omega *= 1.21) {
    const double q = ocean::quantize_omega(omega, period);
    EXPECT_LE(q, omega);
    EXPECT_LT(omega - q, omega0 * (1.0 + 1e-12));
    const double harmonics = q / omega0;
    EXPECT_NEAR(harmonics, std::round(harmonics), 1e-9);
  }
}

// Every combination of the parameter ranges' ends and a few values between, and wavenumbers at
// three per decade over the whole domain (M.2.5).
struct Case {
  double gravity, depth, capillarity;
};
std::vector<Case> domain_cases() {
  std::vector<Case> cases;
  for (double g : {0.1, 9.81, 100.0}) {
    for (double h : {1e-100, 1e-3, 10.0, 1e100, 1e300, ocean::kInfiniteDepth}) {
      for (double t : {0.0, 1e-300, ocean::kSeaWaterCapillarity, 1.0}) cases.push_back({g, h, t});
    }
  }
  return cases;
}
std::vector<double> decades(double lo, double hi) {
  std::vector<double> v;
  for (double x = lo; x <= hi; x *= 2.154434690031884) v.push_back(x);  // 10^(1/3)
  v.push_back(hi);
  return v;
}
std::string describe(const Case& c) {
  return "g = " + ocean::format_number(c.gravity) + ", h = " + ocean::format_number(c.depth) +
         ", T = " + ocean::format_number(c.capillarity);
}
Dispersion make(const Case& c) {
  return Dispersion::make(
             {.gravity_mps2 = c.gravity, .depth_m = c.depth, .capillarity_m3ps2 = c.capillarity})
      .value();
}

TEST(Dispersion, EveryWavenumberOfTheDomainGivesFiniteValuesThatRoundTrip) {
  for (const Case& c : domain_cases()) {
    const Dispersion d = make(c);
    for (double k : decades(Dispersion::kMinWavenumber, Dispersion::kMaxWavenumber)) {
      const double omega = d.omega(k);
      const double phase = d.phase_velocity(k);
      const double group = d.group_velocity(k);
      ASSERT_TRUE(std::isfinite(omega) && omega > 0.0) << describe(c) << ", k = " << k;
      ASSERT_TRUE(std::isfinite(phase) && phase > 0.0) << describe(c) << ", k = " << k;
      ASSERT_TRUE(std::isfinite(group) && group > 0.0) << describe(c) << ", k = " << k;
      // k(ω(k)) = k: F' = c_g/c ≥ ½ bounds the error by twice ω's rounding (M.2.2).
      EXPECT_NEAR(d.wavenumber(omega), k, 1e-14 * k) << describe(c);
      // c_g/c = n ∈ [½, 2] (M.2.3).
      EXPECT_GE(group / phase, 0.5 * (1.0 - 1e-15)) << describe(c) << ", k = " << k;
      EXPECT_LE(group / phase, 2.0) << describe(c) << ", k = " << k;
    }
  }
}

TEST(Dispersion, EveryFrequencyOfTheDomainGivesAConvergedWavenumber) {
  for (const Case& c : domain_cases()) {
    const Dispersion d = make(c);
    ASSERT_LT(d.min_omega(), d.max_omega());
    for (double omega : decades(d.min_omega(), d.max_omega())) {
      const double k = d.wavenumber(omega);
      ASSERT_TRUE(k >= Dispersion::kMinWavenumber && k <= Dispersion::kMaxWavenumber)
          << describe(c) << ", w = " << omega << " gave k = " << k;
      EXPECT_NEAR(d.omega(k), omega, 1e-14 * omega) << describe(c) << ", k = " << k;
    }
  }
}

TEST(Dispersion, GroupVelocityIsTheDerivativeOverTheWholeDomain) {
  // Central difference in ln k: truncation ~h² = 1e-10, rounding ~1e-16/h = 1e-11.
  const double h = 1e-5;
  for (const Case& c : domain_cases()) {
    const Dispersion d = make(c);
    for (double k : decades(1e-199, 1e199)) {
      const double up = k * std::exp(h);
      const double down = k * std::exp(-h);
      const double numeric = (d.omega(up) - d.omega(down)) / (up - down);
      EXPECT_NEAR(d.group_velocity(k), numeric, 1e-8 * numeric) << describe(c) << ", k = " << k;
    }
  }
}

// Deep water without surface tension: ω² = g·k exactly (Lamb 1932, §228), over the domain.
TEST(Dispersion, DeepWaterGravityLimitOverTheDomain) {
  const Dispersion d = make(ocean::kInfiniteDepth);
  for (double k : decades(Dispersion::kMinWavenumber, Dispersion::kMaxWavenumber)) {
    EXPECT_NEAR(d.omega(k), std::sqrt(9.81 * k), 1e-15 * std::sqrt(9.81 * k));
    EXPECT_NEAR(d.group_velocity(k), 0.5 * d.phase_velocity(k), 2e-16 * d.group_velocity(k));
  }
  for (double omega : decades(d.min_omega(), d.max_omega())) {
    const double k = omega / std::sqrt(9.81) * (omega / std::sqrt(9.81));
    EXPECT_NEAR(d.wavenumber(omega), k, 1e-15 * k);
  }
}

// Short capillary waves: ω² = T·k³ once T·k² ≫ g (Lamb 1932, §267). At ω = 1e20 rad/s in sea
// water g/(T·k²) ~ 1e-25, so the capillary root is the answer to double precision.
TEST(Dispersion, CapillaryInverseConvergesFarIntoTheCapillaryRange) {
  const double tension = ocean::kSeaWaterCapillarity;
  const Dispersion d = make(ocean::kInfiniteDepth, tension);
  for (double omega : {1e20, 1e50, 1e100}) {
    const double k = std::cbrt(omega * omega / tension);
    EXPECT_NEAR(d.wavenumber(omega), k, 1e-14 * k) << "w = " << omega;
  }
  // Closer in, gravity still counts: g·k + T·k³ = ω² (M.2.1).
  for (double omega : {1e3, 1e6, 1e10}) {
    const double k = d.wavenumber(omega);
    EXPECT_NEAR(9.81 * k + tension * k * k * k, omega * omega, 1e-14 * omega * omega);
  }
}

// The slowest gravity–capillary wave: c² = g/k + T·k is least at k_m = √(g/T), where
// c_min = (4gT)^¼ (Lamb 1932, §267): for water, c_min ≈ 0.23 m/s at λ_m = 2π/k_m ≈ 1.7 cm.
TEST(Dispersion, CapillaryGravityMinimumPhaseSpeed) {
  const double tension = ocean::kSeaWaterCapillarity;
  const Dispersion d = make(ocean::kInfiniteDepth, tension);
  // Golden-section search for the minimum of c(k) in ln k.
  double a = std::log(10.0);
  double b = std::log(1e4);
  const double r = 0.5 * (std::sqrt(5.0) - 1.0);
  for (int i = 0; i < 200; ++i) {
    const double x1 = b - r * (b - a);
    const double x2 = a + r * (b - a);
    if (d.phase_velocity(std::exp(x1)) < d.phase_velocity(std::exp(x2))) {
      b = x2;
    } else {
      a = x1;
    }
  }
  const double k_min = std::exp(0.5 * (a + b));
  const double c_min = d.phase_velocity(k_min);
  EXPECT_NEAR(c_min, std::pow(4.0 * 9.81 * tension, 0.25), 1e-12);
  EXPECT_NEAR(k_min, std::sqrt(9.81 / tension), 1e-6 * k_min);  // a flat minimum: c'' small
  EXPECT_NEAR(c_min, 0.23, 0.005);
  EXPECT_NEAR(2.0 * ocean::kPi / k_min, 0.017, 0.0005);
  // At the minimum the group velocity equals the phase velocity.
  EXPECT_NEAR(d.group_velocity(k_min), c_min, 1e-6 * c_min);
}

TEST(Dispersion, ValuesOutsideTheDomainAreRejectedWithTheRange) {
  const Dispersion d = make(ocean::kInfiniteDepth, ocean::kSeaWaterCapillarity);
  EXPECT_TRUE(Dispersion::check_wavenumber("k", 1e200).ok());
  EXPECT_TRUE(d.check_omega("omega", 1e20).ok());
  const ocean::Status big = Dispersion::check_wavenumber("k", 1e308);
  EXPECT_EQ(big.message(), "k = 1e+308 is out of range: must be in [1e-200, 1e+200]");
  EXPECT_FALSE(Dispersion::check_wavenumber("k", 5e-324).ok());
  EXPECT_FALSE(Dispersion::check_wavenumber("k", 0.0).ok());
  const ocean::Status tiny = d.check_omega("omega", 1e-300);
  EXPECT_NE(tiny.message().find("omega = 1e-300 is out of range: must be in ["), std::string::npos)
      << tiny.message();
  EXPECT_FALSE(d.check_omega("omega", 1e300).ok());
  EXPECT_FALSE(d.check_omega("omega", std::nan("")).ok());
}

TEST(Dispersion, RejectsBadParameters) {
  EXPECT_FALSE(Dispersion::make({.depth_m = 1e-300}).ok());
  EXPECT_FALSE(Dispersion::make({.gravity_mps2 = 1e3}).ok());
  EXPECT_FALSE(Dispersion::make({.capillarity_m3ps2 = 2.0}).ok());
  EXPECT_FALSE(Dispersion::make({.capillarity_m3ps2 = ocean::kInfiniteDepth}).ok());
  EXPECT_FALSE(Dispersion::make({.depth_m = 0.0}).ok());
  EXPECT_FALSE(Dispersion::make({.depth_m = -5.0}).ok());
  EXPECT_FALSE(Dispersion::make({.depth_m = std::nan("")}).ok());
  EXPECT_FALSE(Dispersion::make({.gravity_mps2 = std::nan("")}).ok());
  EXPECT_FALSE(Dispersion::make({.capillarity_m3ps2 = -1.0}).ok());
  const auto s = Dispersion::make({.depth_m = -5.0}).status();
  EXPECT_NE(s.message().find("depth_m = -5"), std::string::npos);
}

}  // namespace
