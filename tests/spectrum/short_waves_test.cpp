// short_wave_slope_variance and elfouhaily_curvature (ocean/spectrum.hpp): the unified spectrum of
// Elfouhaily et al. (1997) against its own published properties and exact identities of the
// integral over the directions left outside a grid's square.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "ocean/spectrum.hpp"

namespace {

using ocean::ShortWaveParams;
using ocean::SlopeVariance;

SlopeVariance tail(ShortWaveParams p) {
  auto r = ocean::short_wave_slope_variance(p);
  EXPECT_TRUE(r.ok()) << r.status().message();
  return r.ok() ? r.value() : SlopeVariance{};
}

// Over every wave the spectrum is its authors' fit to the glitter: within 25 % of Cox & Munk
// (1954)'s clean-surface σ² = 0.003 + 5.12e-3·U from 3 to 15 m/s (Elfouhaily et al. 1997, §5 and
// Fig. 8, calibrate the gravity–capillary level α_m on those data), and upwind slopes exceed the
// crosswind ones as Cox & Munk's 3.16e-3·U against 0.003 + 1.92e-3·U do from 5 m/s.
TEST(ShortWaves, EveryWaveGivesCoxAndMunksSlopes) {
  for (const double u : {3.0, 5.0, 7.0, 10.0, 12.0, 15.0}) {
    const SlopeVariance s = tail({.wind_speed_mps = u});
    const double cox_munk = 0.003 + 5.12e-3 * u;
    EXPECT_NEAR(s.total() / cox_munk, 1.0, 0.25) << "U = " << u;
    EXPECT_GT(s.upwind, s.crosswind) << "U = " << u;
  }
}

// The curvature spectrum's two published landmarks: the gravity–capillary peak sits at k_m =
// 370 rad/m (eq. 41's F_m is 1 there), and the level α_m of B_h grows with the friction velocity.
TEST(ShortWaves, CurvatureSpectrumHasItsCapillaryPeakAndGrowsWithTheWind) {
  const ShortWaveParams p{.wind_speed_mps = 10.0};
  const double at_peak = ocean::elfouhaily_curvature(370.0, p).curvature;
  EXPECT_GT(at_peak, ocean::elfouhaily_curvature(150.0, p).curvature);
  EXPECT_GT(at_peak, ocean::elfouhaily_curvature(900.0, p).curvature);
  EXPECT_GT(ocean::elfouhaily_curvature(370.0, {.wind_speed_mps = 15.0}).curvature, at_peak);
  // Δ(k) lies in [0, 1]: Φ stays non-negative in every direction.
  for (double k = 0.01; k < 1e4; k *= 1.7) {
    const double d = ocean::elfouhaily_curvature(k, p).spreading;
    EXPECT_GE(d, 0.0) << k;
    EXPECT_LE(d, 1.0) << k;
  }
}

// What a grid leaves out shrinks as the grid grows, and the square's rotation against the wind
// only moves variance between the components within the annulus the square cuts: for
// wavenumbers beyond √2 times the Nyquist, nothing depends on it. Along and across a square
// turned by 90° the components swap.
TEST(ShortWaves, TheSquareLeavesOutLessAsItGrowsAndTurnsWithTheWind) {
  double previous = tail({.wind_speed_mps = 10.0}).total();
  for (const double nyquist : {5.0, 20.0, 80.0, 320.0, 1280.0}) {
    const double t = tail({.wind_speed_mps = 10.0, .grid_nyquist_radpm = nyquist}).total();
    EXPECT_LT(t, previous) << nyquist;
    previous = t;
  }
  const SlopeVariance along = tail({.wind_speed_mps = 10.0, .grid_nyquist_radpm = 60.0});
  const SlopeVariance turned = tail({.wind_speed_mps = 10.0,
                                     .grid_nyquist_radpm = 60.0,
                                     .wind_direction_rad = std::numbers::pi / 2});
  EXPECT_NEAR(turned.upwind, along.upwind, 1e-6 * along.upwind);
  EXPECT_NEAR(turned.crosswind, along.crosswind, 1e-6 * along.crosswind);
  const SlopeVariance diagonal = tail({.wind_speed_mps = 10.0,
                                       .grid_nyquist_radpm = 60.0,
                                       .wind_direction_rad = std::numbers::pi / 4});
  // The total over the annulus depends on the direction only through Δ·cos 2φ, which a square's
  // four-fold symmetry averages out: the same total at any rotation.
  EXPECT_NEAR(diagonal.total(), along.total(), 2e-3 * along.total());
}

// The square holds every wave vector inside its inscribed circle and none beyond its corners:
// the variance left out lies between the full-circle integrals from √2·a and from a.
TEST(ShortWaves, TheSquareLiesBetweenItsCircles) {
  // A circle of radius r leaves out ∫_r^∞ B dln k; compute it from the curvature samples.
  const ShortWaveParams p{.wind_speed_mps = 8.0};
  const auto outside_circle = [&](double r) {
    double sum = 0.0;
    const int steps = 20000;
    const double h = std::log(2e4 / r) / steps;
    for (int i = 0; i <= steps; ++i) {
      const double w = (i == 0 || i == steps) ? 0.5 : 1.0;
      sum += w * ocean::elfouhaily_curvature(r * std::exp(h * i), p).curvature;
    }
    return sum * h;
  };
  const double a = 40.0;
  const double square = tail({.wind_speed_mps = 8.0, .grid_nyquist_radpm = a}).total();
  EXPECT_LT(square, outside_circle(a));
  EXPECT_GT(square, outside_circle(std::sqrt(2.0) * a));
  EXPECT_NEAR(tail({.wind_speed_mps = 8.0, .grid_nyquist_radpm = 0.0}).total(),
              outside_circle(1e-4), 1e-3 * outside_circle(1e-4));
}

TEST(ShortWaves, BadParametersAreRefusedByName) {
  const auto message = [](ShortWaveParams p) {
    auto r = ocean::short_wave_slope_variance(p);
    return r.ok() ? std::string() : r.status().message();
  };
  EXPECT_NE(message({.wind_speed_mps = 0.1}).find("wind_speed_mps"), std::string::npos);
  EXPECT_NE(message({.wind_speed_mps = NAN}).find("wind_speed_mps"), std::string::npos);
  EXPECT_NE(message({.grid_nyquist_radpm = -1.0}).find("grid_nyquist_radpm"), std::string::npos);
  EXPECT_NE(message({.inverse_wave_age = 0.5}).find("inverse_wave_age"), std::string::npos);
  EXPECT_NE(message({.gravity_mps2 = 0.0}).find("gravity_mps2"), std::string::npos);
}

}  // namespace
