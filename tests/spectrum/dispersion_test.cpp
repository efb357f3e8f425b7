// Dispersion relation: published k(ω)/ω(k) values and exact identities.
#include <gtest/gtest.h>

#include <cmath>

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

TEST(Dispersion, RejectsBadParameters) {
  EXPECT_FALSE(Dispersion::make({.depth_m = 0.0}).ok());
  EXPECT_FALSE(Dispersion::make({.depth_m = -5.0}).ok());
  EXPECT_FALSE(Dispersion::make({.depth_m = std::nan("")}).ok());
  EXPECT_FALSE(Dispersion::make({.gravity_mps2 = std::nan("")}).ok());
  EXPECT_FALSE(Dispersion::make({.capillarity_m3ps2 = -1.0}).ok());
  const auto s = Dispersion::make({.depth_m = -5.0}).status();
  EXPECT_NE(s.message().find("depth_m = -5"), std::string::npos);
}

}  // namespace
