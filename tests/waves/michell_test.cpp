// Michell's integral (docs/waves.md W.23) against its closed form for a wall-sided hull of
// parabolic waterlines, f = b·(1 − (x/l)²) to a draught T (Michell 1898; Tuck 1989): the hull
// integral is I(λ) = (1 − e^{−k0λ²T})/(k0λ²)·(−4ib/l²)·(sin(al)/a² − l·cos(al)/a), a = k0·λ, and
// R/ρ = (4g²/πU²)·∫_1^∞ |I|²·λ²/√(λ² − 1) dλ is integrated here by its own quadrature (λ = cosh t,
// a million midpoints) against the library's sampled hull; the wake's height (W.24) is linear in
// the hull's breadth, as thin-ship theory is; bad hulls are refused by name.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <memory>
#include <numbers>

#include "ocean/waves.hpp"

namespace {

using namespace ocean::waves;

constexpr double kG = 9.81;

// The closed form's R/ρ for half length l, half beam b, draught T at speed U.
double closed_form(double l, double b, double T, double U) {
  const double k0 = kG / (U * U);
  const auto integrand = [&](double lambda) {
    const double a = k0 * lambda, q = k0 * lambda * lambda;
    const double x_part = std::sin(a * l) / (a * a) - l * std::cos(a * l) / a;
    const double i_abs = (1.0 - std::exp(-q * T)) / q * 4.0 * b / (l * l) * std::abs(x_part);
    return i_abs * i_abs;
  };
  // λ = cosh t: λ²/√(λ² − 1)·dλ = cosh²t·dt; to λ = cosh 7 ≈ 548 (|I|² falls as λ⁻⁸ beyond).
  constexpr int kSteps = 1000000;
  const double t_end = 7.0, dt = t_end / kSteps;
  double sum = 0.0;
  for (int i = 0; i < kSteps; ++i) {
    const double lambda = std::cosh((i + 0.5) * dt);
    sum += integrand(lambda) * lambda * lambda * dt;
  }
  return 4.0 * kG * kG / (std::numbers::pi * U * U) * sum;
}

ThinHull parabolic(double l, double b, double T, int columns) {
  ThinHull h{.length_m = 2.0 * l, .draft_m = T, .columns = columns, .rows = 1};
  for (int c = 0; c < columns; ++c) {
    const double x = -l + (c + 0.5) * 2.0 * l / columns;
    h.half_breadth_m.push_back(b * (1.0 - (x / l) * (x / l)));
  }
  return h;
}

TEST(Michell, WallSidedParabolicHullMatchesItsClosedForm) {
  // A Wigley-like hull, L/B = 10, L/T = 16, 8 m long, at Fr = 0.25, 0.35 and 0.5. The sampled
  // hull is a staircase of 400 steps: its integral differs from the parabola's by O((Δx/l)²).
  const double l = 4.0, b = 0.4, T = 0.5;
  const ThinHull hull = parabolic(l, b, T, 400);
  ASSERT_TRUE(validate(hull).ok());
  for (double fr : {0.25, 0.35, 0.5}) {
    const double U = fr * std::sqrt(kG * 2.0 * l);
    const double expected = closed_form(l, b, T, U);
    const double got = michell_resistance_per_density(hull, U, kG);
    EXPECT_NEAR(got, expected, 0.01 * expected) << "Fr = " << fr;
  }
}

TEST(Michell, WakeHeightIsLinearInTheBeam) {
  // I is linear in f, R quadratic, and the height ∝ √R: twice the breadth, twice the wake.
  const auto peak = [](double b) {
    LayerParams p;
    p.area = {.origin_m = {-100.0, -50.0}, .size_m = 120.0, .resolution = 256};
    p.wakes.push_back({.x_m = 0.0, .z_m = 0.0, .speed_mps = 5.0, .hull_length_m = 8.0,
                       .thin_hull = std::make_shared<const ThinHull>(parabolic(4.0, b, 0.5, 64))});
    auto layer = LocalLayer::make(std::move(p));
    EXPECT_TRUE(layer.ok());
    LocalFrame f;
    layer.value()->evaluate(0.0, f);
    double m = 0.0;
    for (std::size_t i = 1; i < f.displacement.size(); i += 3)
      m = std::max(m, std::abs(static_cast<double>(f.displacement[i])));
    return m;
  };
  const double one = peak(0.4), two = peak(0.8);
  EXPECT_GT(one, 0.0);
  EXPECT_NEAR(two / one, 2.0, 1e-5);
}

TEST(Michell, BadHullsAreRefusedByName) {
  ThinHull h = parabolic(4.0, 0.4, 0.5, 8);
  h.half_breadth_m[3] = -1.0;
  EXPECT_NE(validate(h).message().find("half_breadth_m"), std::string::npos);
  h = parabolic(4.0, 0.4, 0.5, 8);
  h.rows = 2;
  EXPECT_NE(validate(h).message().find("thin_hull"), std::string::npos);
  h = parabolic(4.0, 0.4, 0.0, 8);
  EXPECT_NE(validate(h).message().find("thin_hull.draft_m"), std::string::npos);
  KelvinWake w;
  w.thin_hull = std::make_shared<const ThinHull>(h);
  EXPECT_FALSE(validate(w).ok());
}

}  // namespace
