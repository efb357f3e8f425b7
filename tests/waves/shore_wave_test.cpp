// The shore wave (ocean/shore_wave.hpp, docs/waves.md W.32–W.37) against linear theory's closed
// forms on planar beaches (Dean & Dalrymple 1991, ch. 4): the wavenumber solves the dispersion
// relation, the group velocity is dω/dk, the direction obeys Snell's law sin θ/c = sin θ0/c0,
// the height follows the shoaling and refraction coefficients K_s·K_r (Green's law d^(−1/4) in
// shallow water) until it reaches the breaking index γ·d. The expected values are computed here
// from the formulas, with a dispersion root found by bisection independently of the library's
// Newton iteration.
#include "ocean/shore_wave.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <numbers>

namespace shore_wave_test {

using ocean::waves::HeightMap;
using ocean::waves::PlacedMap;
using ocean::waves::ShoreWave;
using ocean::waves::ShoreWavePoint;
constexpr double kPi = std::numbers::pi;
constexpr double kG = 9.81;
constexpr double kGamma = 0.78;  // McCowan (1894)

// The root k of ω² = g·k·tanh(k·d) by bisection (Dean & Dalrymple 1991, eq. 4.20).
double dispersion_root(double omega, double d) {
  double lo = 0.0, hi = 10.0 * omega * omega / kG + omega / std::sqrt(kG * d);
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (kG * mid * std::tanh(mid * d) < omega * omega ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}
// c_g = n·c, n = ½(1 + 2kd/sinh 2kd) (Dean & Dalrymple 1991, eq. 4.41).
double group_velocity(double omega, double d) {
  const double k = dispersion_root(omega, d);
  return 0.5 * (1.0 + 2.0 * k * d / std::sinh(2.0 * k * d)) * omega / k;
}

TEST(ShoreWave, WavenumberSolvesTheDispersionRelation) {
  for (double period : {2.0, 5.0, 8.0, 14.0, 20.0}) {
    const double omega = 2.0 * kPi / period;
    for (double d : {0.01, 0.1, 0.5, 2.0, 10.0, 50.0, 300.0, 3000.0}) {
      const double k = ocean::waves::shore_wavenumber(omega, d, kG);
      EXPECT_NEAR(kG * k * std::tanh(k * d), omega * omega, 1e-12 * omega * omega)
          << "T = " << period << " s, d = " << d << " m";
      EXPECT_NEAR(k, dispersion_root(omega, d), 1e-10 * k);
      // c_g = dω/dk at fixed d, by a central difference of ω(k) = √(g·k·tanh(k·d)).
      const auto w = [d](double kk) { return std::sqrt(kG * kk * std::tanh(kk * d)); };
      const double dk = 1e-5 * k;
      EXPECT_NEAR(ocean::waves::shore_group_velocity(omega, d, kG),
                  (w(k + dk) - w(k - dk)) / (2.0 * dk), 1e-7 * omega / k);
    }
    // The limits: ω²/g in deep water, ω/√(g·d) in shallow water (to (kd)²/6).
    EXPECT_EQ(ocean::waves::shore_wavenumber(omega, std::numeric_limits<double>::infinity(), kG),
              omega * omega / kG);
    const double d = 1e-4, k = ocean::waves::shore_wavenumber(omega, d, kG);
    EXPECT_NEAR(k, omega / std::sqrt(kG * d), 0.2 * k * k * d * d * k);
  }
  EXPECT_TRUE(std::isinf(ocean::waves::shore_wavenumber(1.0, 0.0, kG)));
  EXPECT_EQ(ocean::waves::shore_group_velocity(1.0, -1.0, kG), 0.0);
  EXPECT_EQ(ocean::waves::shore_group_velocity(1.0, 1e9, kG), kG / 2.0);  // deep: g/(2ω)
}

// A planar beach whose contours make the angle φ with the z axis: a plateau kPlateau_m deep, then
// a bottom rising at 1:5 along n̂ = (cos φ, sin φ) to the shore at n̂·x = kShore_m, then land;
// 400 × 400 cells of 1.5 m from the origin. Its offshore edge (x = 0) is deep: kd ≥ 6.4.
constexpr double kPlateau_m = 40.0, kSlope = 0.2, kShore_m = 405.0, kCell_m = 1.5;
constexpr int kCells = 400;
constexpr double kPeriod_s = 5.0;

double beach_depth(double phi, double x, double z) {
  const double u = x * std::cos(phi) + z * std::sin(phi);
  return std::min(kPlateau_m, kSlope * (kShore_m - u));
}

PlacedMap beach(double phi) {
  auto map = std::make_shared<HeightMap>();
  map->rows = map->cols = kCells;
  for (int r = 0; r < kCells; ++r)
    for (int c = 0; c < kCells; ++c)
      map->values.push_back(
          static_cast<float>(beach_depth(phi, (c + 0.5) * kCell_m, (r + 0.5) * kCell_m)));
  return {.map = map, .size_m = kCells * kCell_m};
}

// Linear theory at depth d for a wave of deep-water incidence θ0 on straight contours: Snell's
// sin θ = (k0/k)·sin θ0 and H/H0 = K_s·K_r = √(c_g0/c_g)·√(cos θ0/cos θ).
struct Expected {
  double sin_theta, height_ratio;
};
Expected linear_theory(double d, double theta0) {
  const double omega = 2.0 * kPi / kPeriod_s, k0 = omega * omega / kG;
  const double k = dispersion_root(omega, d);
  const double s = k0 / k * std::sin(theta0);
  const double cos_theta = std::sqrt(1.0 - s * s);
  const double ks = std::sqrt(kG / (2.0 * omega) / group_velocity(omega, d));
  return {s, ks * std::sqrt(std::cos(theta0) / cos_theta)};
}

struct Error {
  double snell = 0.0;   // the largest error of the direction θ, rad
  double height = 0.0;  // the largest relative error of H
  int cells = 0;
  double shallowest_m = 1e9;
};

// Compares every cell centre clear of the wedge that the upwind side edge (z = 0) shades — rays
// there start off the offshore edge, which has no wave to send — and unbroken, over water of at
// least 0.2 m.
Error compare(const ShoreWave& wave, double phi, double theta0) {
  Error e;
  const double tn = std::cos(phi), tz = std::sin(phi);  // n̂
  const double max_ray_slope = std::tan(phi + theta0);  // the rays turn towards n̂
  for (int r = 0; r < kCells; ++r) {
    for (int c = 0; c < kCells; ++c) {
      const double x = (c + 0.5) * kCell_m, z = (r + 0.5) * kCell_m;
      if (z < max_ray_slope * x + 10.0 * kCell_m || z > (kCells - 4) * kCell_m) continue;
      const ShoreWavePoint q = wave.at(x, z);
      if (q.depth_m < 0.2 || q.breaking) continue;
      const Expected want = linear_theory(q.depth_m, theta0);
      // sin θ from the direction: its component along the contours, t̂ = (−sin φ, cos φ).
      const double sin_theta = -q.direction[0] * tz + q.direction[1] * tn;
      e.snell = std::max(e.snell, std::abs(std::asin(sin_theta) - std::asin(want.sin_theta)));
      e.height = std::max(
          e.height, std::abs(q.height_m / (wave.params().deep_height_m * want.height_ratio) - 1.0));
      ++e.cells;
      e.shallowest_m = std::min(e.shallowest_m, q.depth_m);
    }
  }
  return e;
}

TEST(ShoreWave, SnellAndShoalingOnAPlanarBeachAlongTheGrid) {
  const double theta0 = 30.0 * kPi / 180.0;
  const auto made = ShoreWave::make({.bathymetry = beach(0.0),
                                     .period_s = kPeriod_s,
                                     .deep_height_m = 0.5,
                                     .direction_deg = 30.0});
  ASSERT_TRUE(made.ok()) << made.status().message();
  const Error e = compare(made.value(), 0.0, theta0);
  std::printf(
      "beach along the grid, θ0 = 30°: %d cells down to d = %.2f m, θ within %.2e°, "
      "H/H0 = K_s·K_r within %.2e\n",
      e.cells, e.shallowest_m, e.snell * 180.0 / kPi, e.height);
  ASSERT_GT(e.cells, 10000);
  ASSERT_LT(e.shallowest_m, 1.0);
  // On contours along the grid the discrete phase is k0·sin θ0·z + Σ h·√(k² − k0²·sin²θ0) and
  // the donor-cell flux keeps R·cos θ exactly: both hold to rounding.
  EXPECT_LT(e.snell, 1e-9);
  EXPECT_LT(e.height, 1e-9);
}

TEST(ShoreWave, SnellAndShoalingOnAPlanarBeachAcrossTheGrid) {
  // Contours at 20° to the grid, the wave at 20° to their normal: the first-order schemes'
  // errors show here.
  const double phi = 20.0 * kPi / 180.0, theta0 = 20.0 * kPi / 180.0;
  const auto made = ShoreWave::make({.bathymetry = beach(phi),
                                     .period_s = kPeriod_s,
                                     .deep_height_m = 0.5,
                                     .direction_deg = 40.0});
  ASSERT_TRUE(made.ok()) << made.status().message();
  const Error e = compare(made.value(), phi, theta0);
  std::printf(
      "beach at 20° to the grid, θ0 = 20°: %d cells down to d = %.2f m, θ within %.3f°, "
      "H/H0 = K_s·K_r within %.2e\n",
      e.cells, e.shallowest_m, e.snell * 180.0 / kPi, e.height);
  ASSERT_GT(e.cells, 5000);
  ASSERT_LT(e.shallowest_m, 1.0);
  // First order in the cell against the scale of k's change: the direction within 1.5° (the
  // largest error lies where the water is shallowest, the wavelength 10 cells), the height within
  // 1 %.
  EXPECT_LT(e.snell, 1.5 * kPi / 180.0);
  EXPECT_LT(e.height, 0.01);
}

TEST(ShoreWave, GreensLawInShallowWater) {
  // Normal incidence: K_r = 1 and, where kd ≪ 1, c_g → √(g·d), so H ∝ d^(−1/4) (Green 1838).
  const auto made = ShoreWave::make({.bathymetry = beach(0.0),
                                     .period_s = kPeriod_s,
                                     .deep_height_m = 0.05,
                                     .direction_deg = 0.0});
  ASSERT_TRUE(made.ok()) << made.status().message();
  const ShoreWave& wave = made.value();
  const double z = 300.0;
  const ShoreWavePoint a = wave.at(kShore_m - 0.8 / kSlope, z);  // d = 0.8 m
  const ShoreWavePoint b = wave.at(kShore_m - 0.2 / kSlope, z);  // d = 0.2 m
  ASSERT_FALSE(b.breaking);
  ASSERT_LT(a.wavenumber_radpm * a.depth_m, 0.4);
  const double green = std::pow(a.depth_m / b.depth_m, 0.25);
  std::printf("Green's law from d = %.3f to %.3f m: H ratio %.5f, (d1/d2)^(1/4) = %.5f\n",
              a.depth_m, b.depth_m, b.height_m / a.height_m, green);
  // The shallow-water limit's error: c_g/√(g·d) = 1 − (kd)²/2 + O((kd)⁴), so H·d^(1/4) varies by
  // about (kd)²/4 between the two depths, kd that of the deeper one.
  const double kd = a.wavenumber_radpm * a.depth_m;
  EXPECT_NEAR(b.height_m / a.height_m, green, green * kd * kd / 4.0);
  EXPECT_NEAR(a.refraction, 1.0, 1e-9);
}

TEST(ShoreWave, BreaksWhereTheShoaledHeightReachesTheBreakingIndex) {
  const double theta0 = 30.0 * kPi / 180.0, h0 = 0.5;
  const auto made = ShoreWave::make({.bathymetry = beach(0.0),
                                     .period_s = kPeriod_s,
                                     .deep_height_m = h0,
                                     .direction_deg = 30.0,
                                     .breaking_index = kGamma});
  ASSERT_TRUE(made.ok()) << made.status().message();
  // The analytic onset: H0·K_s·K_r(d) = γ·d, bisected on d.
  double lo = 1e-3, hi = 5.0;
  for (int i = 0; i < 100; ++i) {
    const double mid = 0.5 * (lo + hi);
    (h0 * linear_theory(mid, theta0).height_ratio > kGamma * mid ? lo : hi) = mid;
  }
  const double x_break = kShore_m - hi / kSlope;
  double onset = -1.0;
  for (double x = 300.0; x < kShore_m; x += 0.1 * kCell_m) {
    if (made.value().at(x, 500.0).breaking) {
      onset = x;
      break;
    }
  }
  std::printf("onset of breaking, H0 = %.2f m: analytic x = %.3f m (d_b = %.4f m), found %.3f m\n",
              h0, x_break, hi, onset);
  EXPECT_NEAR(onset, x_break, kCell_m);
  for (double x = onset; x < kShore_m - 0.5; x += 0.37) {
    const ShoreWavePoint q = made.value().at(x, 500.0);
    EXPECT_NEAR(q.height_m, kGamma * q.depth_m, 1e-12) << "x = " << x;
  }
}

// The crests seen in the heights themselves: the phase ψ of h = (H/2)·cos ψ read from two
// instants a quarter period apart, its gradient by finite differences over a few metres, gives
// the direction the crests travel; it turns from the deep-water direction towards the beach's
// normal as Snell's law says.
TEST(ShoreWave, CrestsInTheHeightsTurnTowardsTheContours) {
  const double phi = 20.0 * kPi / 180.0, theta0 = 20.0 * kPi / 180.0;
  const auto made = ShoreWave::make({.bathymetry = beach(phi),
                                     .period_s = kPeriod_s,
                                     .deep_height_m = 0.3,
                                     .direction_deg = 40.0});
  ASSERT_TRUE(made.ok()) << made.status().message();
  const ShoreWave& wave = made.value();
  const auto psi = [&](double x, double z) {
    const double c = wave.displacement_at(x, z, 0.0, 0.0)[1];
    const double s = wave.displacement_at(x, z, kPeriod_s / 4.0, 0.0)[1];
    return std::atan2(s, c);  // cos(ψ − π/2) = sin ψ
  };
  const auto wrap = [](double a) { return std::remainder(a, 2.0 * kPi); };
  const double tx = -std::sin(phi), tz = std::cos(phi);  // along the contours
  double previous = 1.0;
  for (double d : {30.0, 8.0, 3.0, 1.5}) {
    // On the line z = 520 m, where the beach's depth is d.
    const double z = 520.0, x = (kShore_m - d / kSlope - z * std::sin(phi)) / std::cos(phi);
    const double step = 0.5;
    const double gx = wrap(psi(x + step, z) - psi(x - step, z)) / (2.0 * step);
    const double gz = wrap(psi(x, z + step) - psi(x, z - step)) / (2.0 * step);
    const double sin_theta = (gx * tx + gz * tz) / std::hypot(gx, gz);
    const double want = linear_theory(d, theta0).sin_theta;
    std::printf("d = %4.1f m: crests travel at θ = %.2f° to the beach's normal, Snell %.2f°\n", d,
                std::asin(sin_theta) * 180.0 / kPi, std::asin(want) * 180.0 / kPi);
    EXPECT_NEAR(std::asin(sin_theta), std::asin(want), 1.0 * kPi / 180.0) << "d = " << d;
    EXPECT_LT(sin_theta, previous);  // turning towards the normal as the water shoals
    previous = sin_theta;
  }
}

TEST(ShoreWave, RejectsBadParameters) {
  const auto check = [](ocean::waves::ShoreWaveParams p, const char* field) {
    const ocean::Status s = ocean::waves::validate(p);
    EXPECT_FALSE(s.ok()) << field;
    EXPECT_NE(s.message().find(field), std::string::npos) << s.message();
  };
  const PlacedMap map = beach(0.0);
  check({}, "bathymetry");
  check({.bathymetry = map, .period_s = 0.1}, "period_s");
  check({.bathymetry = map, .deep_height_m = -1.0}, "deep_height_m");
  check({.bathymetry = map, .direction_deg = std::nan("")}, "direction_deg");
  check({.bathymetry = map, .breaking_index = 2.0}, "breaking_index");
  EXPECT_TRUE(ocean::waves::validate(ocean::waves::ShoreWaveParams{.bathymetry = map}).ok());
}

}  // namespace shore_wave_test
