// Directional spreading: normalisation of every model, published values (xdyn, WAFO) and the
// published coefficients of Mitsuyasu, Hasselmann and Donelan–Banner.
#include <gtest/gtest.h>

#include <cmath>

#include "ocean/spectrum.hpp"
#include "spectrum/test_util.hpp"

namespace {

using ocean::Spreading;
using ocean::SpreadingModel;
using ocean::SpreadingParams;
using ocean_test::relative_error;

constexpr double kPi = ocean::kPi;

Spreading make(SpreadingParams p, double omega_p = 1.0, double wind = 10.0) {
  return Spreading::make(p, {.omega_p = omega_p, .wind_speed_mps = wind}).value();
}

// ∫D dθ over (−π, π]. For small s the cos-2s family has a cusp at ±π, (π − |θ|)^(2s), that
// Simpson's rule resolves badly; θ = π·c(c(x)) with c(x) = (3x − x³)/2 flattens it to
// (1 − |x|)^(8s+3).
double integral(const Spreading& d, double omega) {
  const auto c = [](double x) { return 0.5 * (3.0 * x - x * x * x); };
  const auto dc = [](double x) { return 1.5 * (1.0 - x * x); };
  return ocean_test::simpson(
      [&](double x) { return d(omega, kPi * c(c(x))) * kPi * dc(c(x)) * dc(x); }, -1.0, 1.0, 20000);
}

TEST(Spreading, EveryModelIntegratesToOne) {
  const SpreadingParams models[] = {
      {.model = SpreadingModel::power_cosine},
      {.model = SpreadingModel::power_cosine, .alpha = 0.0},
      {.model = SpreadingModel::power_cosine, .alpha = 0.4},
      {.model = SpreadingModel::power_cosine, .s = 2.0, .counter_wave_suppression = false},
      {.model = SpreadingModel::cos2s, .s = 0.0},
      {.model = SpreadingModel::cos2s, .s = 15.0},
      {.model = SpreadingModel::cos2s, .s = 300.0},
      {.model = SpreadingModel::mitsuyasu},
      {.model = SpreadingModel::hasselmann},
      {.model = SpreadingModel::donelan_banner},
  };
  for (const SpreadingParams& p : models) {
    const Spreading d = make(p, 0.8, 12.0);
    for (double ratio : {0.3, 0.7, 0.95, 1.0, 1.3, 1.6, 2.5, 6.0}) {
      EXPECT_NEAR(integral(d, ratio * 0.8), 1.0, 1e-7)  // quadrature error of the |cos| kinks
          << ocean::to_string(p.model) << " ratio " << ratio;
    }
  }
}

// xdyn @4c4db1c code/environment_models/unit_tests/src/Cos2sDirectionalSpreadingTest.cpp
// lines 34–57 (closed forms generated with Maple).
TEST(Spreading, XdynCos2sValues) {
  struct Row {
    double psi0, s, psi, expected;
  };
  const Row rows[] = {{kPi / 4, 3, kPi / 3, 8 * std::pow(std::cos(kPi / 24), 6) / (5 * kPi)},
                      {kPi / 4, 4, kPi / 3, 64 * std::pow(std::cos(kPi / 24), 8) / (35 * kPi)},
                      {kPi / 4, 5, kPi / 3, 128 * std::pow(std::cos(kPi / 24), 10) / (63 * kPi)},
                      {kPi / 5, 1, kPi / 6, std::pow(std::cos(kPi / 60), 2) / kPi},
                      {kPi / 5, 2, kPi / 6, 4 * std::pow(std::cos(kPi / 60), 4) / (3 * kPi)}};
  for (const Row& r : rows) {
    const Spreading d = make({.model = SpreadingModel::cos2s, .s = r.s});
    EXPECT_NEAR(d(1.0, r.psi - r.psi0), r.expected, 1e-15);
  }
}

// WAFO (pywafo @c831ec8) src/wafo/spectrum/tests/test_models.py lines 73–128: cos-2s with
// s = 15 at θ = 2πi/49 (decimal = 5; 9 digits printed).
TEST(Spreading, WafoCos2sTable) {
  const Spreading d = make({.model = SpreadingModel::cos2s, .s = 15.0});
  const struct {
    int i;
    double expected;
  } rows[] = {{0, 1.10168934},     {1, 1.03576796},      {2, 0.860302298},    {3, 0.630309013},
              {4, 0.406280137},    {5, 0.229514882},     {6, 0.113052757},    {8, 0.0176754409},
              {10, 0.00143800617}, {12, 5.39672445e-05}, {24, 1.65021852e-45}};
  for (const auto& r : rows) {
    const double theta = 2.0 * kPi * r.i / 49.0;
    EXPECT_LT(relative_error(d(1.0, theta), r.expected), 1e-8) << "i " << r.i;
    EXPECT_LT(relative_error(d(1.0, -theta), r.expected), 1e-8);
  }
}

// Closed-form integral of the power-cosine: ∫|cos θ|² dθ over the circle is π.
TEST(Spreading, PowerCosineIntegral) {
  EXPECT_NEAR(ocean::power_cosine_integral(2.0, 1.0), kPi, 1e-14);
  EXPECT_NEAR(ocean::power_cosine_integral(0.0, 1.0), 2.0 * kPi, 1e-14);
  EXPECT_NEAR(ocean::power_cosine_integral(1.0, 0.0), 2.0, 1e-14);
  EXPECT_NEAR(ocean::cos2s_normalization(0.0), 1.0 / (2.0 * kPi), 1e-15);
}

// Aebi, VR Ocean, eqs. 6–8: counter-wave energy σ(α) on |θ| > π/2 and s(α) = 1 + 5α².
TEST(Spreading, PowerCosineSeedRules) {
  const Spreading d = make({.model = SpreadingModel::power_cosine, .alpha = 1.0});
  EXPECT_EQ(d.spread_parameter(1.0), 6.0);
  EXPECT_NEAR(d(1.0, kPi) / d(1.0, 0.0), 0.01, 1e-12);
  const Spreading half = make({.model = SpreadingModel::power_cosine, .alpha = 0.5});
  EXPECT_EQ(half.spread_parameter(1.0), 2.25);
  EXPECT_NEAR(half(1.0, kPi) / half(1.0, 0.0), 0.01 + 0.49 * 0.25, 1e-12);
  const Spreading symmetric =
      make({.model = SpreadingModel::power_cosine, .s = 2.0, .counter_wave_suppression = false});
  EXPECT_NEAR(symmetric(1.0, kPi), symmetric(1.0, 0.0), 1e-15);
  EXPECT_NEAR(symmetric(1.0, 0.0), 1.0 / kPi, 1e-15);
}

// Mitsuyasu et al. (1975): s_max = 11.5·(U·ωp/g)^−2.5 at the peak, ∝ (ω/ωp)^5 below, ^−2.5 above.
TEST(Spreading, MitsuyasuCoefficients) {
  const double g = 9.81;
  const double u = 10.0;
  const double wp = g / u;  // U·ωp/g = 1 ⇒ s_max = 11.5
  const Spreading d = make({.model = SpreadingModel::mitsuyasu}, wp, u);
  EXPECT_NEAR(d.spread_parameter(wp), 11.5, 1e-12);
  EXPECT_NEAR(d.spread_parameter(0.5 * wp), 11.5 / 32.0, 1e-12);
  EXPECT_NEAR(d.spread_parameter(2.0 * wp), 11.5 * std::pow(2.0, -2.5), 1e-12);
}

// Hasselmann, Dunckel & Ewing (1980): s = 6.97·(f/fp)^4.06 below 1.05·fp, 9.77·(f/fp)^μ above,
// μ = −2.33 − 1.45·(U/cp − 1.17).
TEST(Spreading, HasselmannCoefficients) {
  const double g = 9.81;
  const double wp = 1.0;
  const double u = 1.17 * g / wp;  // U/cp = 1.17 ⇒ μ = −2.33
  const Spreading d = make({.model = SpreadingModel::hasselmann}, wp, u);
  EXPECT_NEAR(d.spread_parameter(wp), 6.97, 1e-12);
  EXPECT_NEAR(d.spread_parameter(0.5 * wp), 6.97 * std::pow(0.5, 4.06), 1e-12);
  EXPECT_NEAR(d.spread_parameter(2.0 * wp), 9.77 * std::pow(2.0, -2.33), 1e-12);
}

// Donelan, Hamilton & Hui (1985) β_s = 2.61·r^1.3 (r < 0.95), 2.28·r^−1.3 (< 1.6) and Banner
// (1990) 10^ε above, which joins the middle branch at r = 1.6 to < 1e-4 (so ln is of r², not
// (ln r)²); the 0.95 junction jumps by 0.18 % in the published coefficients.
TEST(Spreading, DonelanBannerCoefficients) {
  EXPECT_NEAR(ocean::donelan_banner_beta(1.0), 2.28, 1e-15);
  EXPECT_NEAR(ocean::donelan_banner_beta(0.5), 2.61 * std::pow(0.5, 1.3), 1e-15);
  const double below = ocean::donelan_banner_beta(1.6 - 1e-12);
  const double above = ocean::donelan_banner_beta(1.6);
  EXPECT_LT(relative_error(above, below), 1e-4);
  EXPECT_LT(
      relative_error(ocean::donelan_banner_beta(0.95 - 1e-12), ocean::donelan_banner_beta(0.95)),
      2e-3);
  // sech² form with its normaliser β/(2·tanh βπ).
  const Spreading d = make({.model = SpreadingModel::donelan_banner});
  EXPECT_NEAR(d(1.0, 0.0), 2.28 / (2.0 * std::tanh(2.28 * kPi)), 1e-14);
}

TEST(Spreading, RejectsBadInput) {
  const ocean::SpreadingContext context{.omega_p = 1.0, .wind_speed_mps = 10.0};
  EXPECT_FALSE(
      Spreading::make({.model = SpreadingModel::power_cosine, .alpha = 1.5}, context).ok());
  EXPECT_FALSE(Spreading::make({.model = SpreadingModel::power_cosine, .s = -1.0}, context).ok());
  EXPECT_FALSE(Spreading::make({.model = SpreadingModel::cos2s}, context).ok());
  EXPECT_FALSE(Spreading::make({.model = SpreadingModel::mitsuyasu, .s = 3.0}, context).ok());
  EXPECT_FALSE(Spreading::make({.model = SpreadingModel::mitsuyasu}, {.omega_p = 1.0}).ok());
  EXPECT_FALSE(Spreading::make({.model = SpreadingModel::donelan_banner}, {}).ok());
  EXPECT_FALSE(ocean::parse_spreading_model("gaussian").ok());
}

}  // namespace
