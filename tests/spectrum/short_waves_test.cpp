// short_wave_slope_variance and elfouhaily_curvature (ocean/spectrum.hpp): the unified spectrum of
// Elfouhaily et al. (1997) against its own published properties and exact identities of the
// integral over the directions left outside a grid's square.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
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

// The sum of sines standing in for a band of the short waves (M.9.4) carries the band's slope
// variance: the total against the curvature spectrum integrated here by the trapezoid rule over
// 20 000 steps of ln k (∫B d ln k, an independent quadrature of eq. 30), to 10⁻⁴; the up- and
// crosswind parts against ∫B·(½ ± Δ/4) d ln k (eq. 49 over the circle) within 10 % (three
// directions per bin at the spreading's quantiles); every wave runs within 90° of downwind; the
// draw depends on the seed alone.
TEST(ShortWaves, ComponentsCarryTheBandsSlopeVariance) {
  for (const double u : {5.0, 10.0, 15.0}) {
    ocean::ShortWaveComponentParams p{.waves = {.wind_speed_mps = u, .wind_direction_rad = 0.7},
                                      .k_min_radpm = 87.5,
                                      .k_max_radpm = 3000.0,
                                      .seed = 7};
    auto waves = ocean::short_wave_components(p);
    ASSERT_TRUE(waves.ok()) << waves.status().message();
    ASSERT_EQ(waves.value().size(), 48u);
    double total = 0.0, up = 0.0, cross = 0.0, last_k = 0.0;
    for (const ocean::ShortWaveComponent& w : waves.value()) {
      const double k = std::hypot(w.kx_radpm, w.kz_radpm);
      EXPECT_GE(k, p.k_min_radpm);
      EXPECT_LE(k, p.k_max_radpm);
      EXPECT_GE(k, last_k);  // by increasing k
      last_k = k;
      const double phi = std::atan2(w.kz_radpm, w.kx_radpm) - 0.7;
      EXPECT_GT(std::cos(phi), -1e-12);  // downwind half
      total += w.slope_variance();
      up += w.slope_variance() * std::cos(phi) * std::cos(phi);
      cross += w.slope_variance() * std::sin(phi) * std::sin(phi);
      // Gravity–capillary dispersion (eq. 4): ω² = g·k·(1 + (k/k_m)²).
      EXPECT_NEAR(w.omega_radps * w.omega_radps,
                  9.81 * k * (1.0 + (k / 370.0) * (k / 370.0)), 1e-9 * w.omega_radps * w.omega_radps);
    }
    constexpr int kSteps = 20000;
    const double h = std::log(p.k_max_radpm / p.k_min_radpm) / kSteps;
    double band = 0.0, band_up = 0.0, band_cross = 0.0;
    for (int i = 0; i <= kSteps; ++i) {
      const auto b = ocean::elfouhaily_curvature(p.k_min_radpm * std::exp(h * i), p.waves);
      const double trapezoid = (i == 0 || i == kSteps) ? 0.5 : 1.0;
      band += trapezoid * h * b.curvature;
      band_up += trapezoid * h * b.curvature * (0.5 + 0.25 * b.spreading);
      band_cross += trapezoid * h * b.curvature * (0.5 - 0.25 * b.spreading);
    }
    std::printf("U = %4.1f m/s: sines %.5f (up %.5f, cross %.5f), spectrum %.5f (%.5f, %.5f)\n", u,
                total, up, cross, band, band_up, band_cross);
    EXPECT_NEAR(total, band, 1e-4 * band) << "U = " << u;
    EXPECT_NEAR(up, band_up, 0.1 * band_up) << "U = " << u;
    EXPECT_NEAR(cross, band_cross, 0.1 * band_cross) << "U = " << u;
    auto again = ocean::short_wave_components(p);
    ASSERT_TRUE(again.ok());
    EXPECT_EQ(again.value().front().phase_rad, waves.value().front().phase_rad);
    p.seed = 8;
    EXPECT_NE(ocean::short_wave_components(p).value().front().phase_rad,
              waves.value().front().phase_rad);
  }
}

// Elfouhaily et al.'s (1997) eq. 4 at its own landmark: the gravity–capillary waves' slowest phase
// speed c_m = 0.23 m/s at k_m = 370 rad/m (λ = 1.7 cm).
TEST(ShortWaves, PhaseSpeedHasItsCapillaryMinimum) {
  EXPECT_NEAR(ocean::capillary_gravity_phase_speed(370.0), 0.23, 0.005);
  EXPECT_LT(ocean::capillary_gravity_phase_speed(370.0), ocean::capillary_gravity_phase_speed(300.0));
  EXPECT_LT(ocean::capillary_gravity_phase_speed(370.0), ocean::capillary_gravity_phase_speed(450.0));
}

TEST(ShortWaves, BadComponentParametersAreRefusedByName) {
  const auto message = [](ocean::ShortWaveComponentParams p) {
    auto r = ocean::short_wave_components(p);
    return r.ok() ? std::string() : r.status().message();
  };
  EXPECT_NE(message({.k_min_radpm = -1.0}).find("k_min_radpm"), std::string::npos);
  EXPECT_NE(message({.k_max_radpm = NAN}).find("k_max_radpm"), std::string::npos);
  EXPECT_NE(message({.k_min_radpm = 500.0, .k_max_radpm = 400.0}).find("k_max_radpm"),
            std::string::npos);
  EXPECT_NE(message({.bins = 0}).find("bins"), std::string::npos);
  EXPECT_NE(message({.per_bin = 17}).find("per_bin"), std::string::npos);
  EXPECT_NE(message({.waves = {.wind_speed_mps = 0.1}}).find("wind_speed_mps"), std::string::npos);
}

}  // namespace
