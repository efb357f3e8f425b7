// The far field's CPU reference (ocean/far_field.hpp, docs/rendering.md R.13): VR-GIS FFT+Perlin's
// Hermite ratio (eq. 6) and its identities, the unit noise's moments against a direct
// measurement, the fitted noise's height variance and mean-square slope against both cascade 0's
// spectrum integral and the simulated cascade 0 itself, and bad ranges. No device needed.
#include "ocean/far_field.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "ocean/backends.hpp"
#include "render/shaders/far_noise.h"

namespace {

using ocean::render::FarFieldRange;

// The moderate preset's sea without choppiness: the unit normals are then exactly the height
// field's gradient, which is what the noise is fitted to.
ocean::SimulationConfig moderate_heights() {
  ocean::SimulationConfig c;
  c.cascade_patch_sizes_m = {1000.0, 233.0, 57.0, 13.0};
  c.choppiness = 0.0;
  return c;
}

// The noise's measured statistics over a square of `cells` octave-0 cells on a side, 8 samples a
// cell (far more samples than the sampling error of the lattice needs).
struct Measured {
  double height = 0.0, slope = 0.0;
};
Measured measure(const ocean::render::FarFieldNoise& noise, double cells) {
  const double side = cells * noise.cell_m[0];
  const int n = static_cast<int>(cells * 8);
  double h2 = 0.0, s2 = 0.0, h1 = 0.0;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const auto s = ocean::render::far_field_noise(noise, 12345.0 + side * (i + 0.37) / n,
                                                    -6789.0 + side * (j + 0.71) / n);
      h1 += s.height_m;
      h2 += s.height_m * s.height_m;
      s2 += s.slope_x * s.slope_x + s.slope_z * s.slope_z;
    }
  const double count = static_cast<double>(n) * n;
  return {.height = h2 / count - (h1 / count) * (h1 / count), .slope = s2 / count};
}

TEST(FarField, HermiteRatioIsSeedEquationSix) {
  const FarFieldRange r{.near_m = 100.0, .far_m = 300.0};
  EXPECT_EQ(ocean::render::far_field_ratio(r, 0.0), 0.0);
  EXPECT_EQ(ocean::render::far_field_ratio(r, 100.0), 0.0);
  EXPECT_DOUBLE_EQ(ocean::render::far_field_ratio(r, 200.0), 0.5);
  EXPECT_DOUBLE_EQ(ocean::render::far_field_ratio(r, 150.0), -2.0 / 64.0 + 3.0 / 16.0);
  EXPECT_EQ(ocean::render::far_field_ratio(r, 300.0), 1.0);
  EXPECT_EQ(ocean::render::far_field_ratio(r, 1e9), 1.0);
  // Zero slope at both ends: the blend starts and ends without a crease.
  EXPECT_NEAR(ocean::render::far_field_ratio(r, 100.0 + 1e-3), 0.0, 1e-10);
  EXPECT_NEAR(ocean::render::far_field_ratio(r, 300.0 - 1e-3), 1.0, 1e-10);
}

// The quadrature's expectations against the hashed lattice's actual field: one octave of unit
// amplitude and spacing, measured over 256² cells (65 536 independent gradients: the variance's
// sampling spread is below 1 %; 3 % is more than 4σ).
TEST(FarField, UnitNoiseMomentsMatchTheHashedLattice) {
  const ocean::render::UnitNoiseMoments unit = ocean::render::unit_noise_moments();
  ocean::render::FarFieldNoise one;
  one.cell_m = {1.0, 1.0, 1.0};
  one.amplitude_m = {1.0, 0.0, 0.0};
  const Measured m = measure(one, 256.0);
  EXPECT_NEAR(m.height / unit.height_variance, 1.0, 0.03);
  EXPECT_NEAR(m.slope / (2.0 * unit.slope_variance), 1.0, 0.03);
}

// The fitted noise carries cascade 0's height variance and mean-square slope (of the normals the
// simulation computes, central differences by default): measured over 256² octave-0 cells within
// 3 % of the spectrum's band sums; and those sums agree with the simulated cascade 0 (8 seeds)
// within 4σ of that measurement's sampling spread.
TEST(FarField, NoiseMatchesCascadeZeroHeightAndSlopeVariance) {
  const ocean::SimulationConfig config = moderate_heights();
  auto noise = ocean::render::fit_far_field_noise(config);
  ASSERT_TRUE(noise.ok()) << noise.status().message();
  const ocean::render::BandStatistics target = noise.value().target;
  ASSERT_GT(target.height_variance_m2, 0.0);
  const Measured m = measure(noise.value(), 256.0);
  std::printf(
      "cascade 0: height variance %.4f m² (noise %.4f), mean-square slope %.5f (noise "
      "%.5f); octaves %.1f, %.1f, %.1f m\n",
      target.height_variance_m2, m.height, target.slope_variance, m.slope, noise.value().cell_m[0],
      noise.value().cell_m[1], noise.value().cell_m[2]);
  EXPECT_NEAR(m.height / target.height_variance_m2, 1.0, 0.03);
  EXPECT_NEAR(m.slope / target.slope_variance, 1.0, 0.03);

  constexpr int kSeeds = 8;
  double fft_h = 0.0, fft_s = 0.0;
  for (int seed = 1; seed <= kSeeds; ++seed) {
    ocean::SimulationConfig c = config;
    c.seed = static_cast<std::uint64_t>(seed);
    auto sim = ocean::make_simulator(c, "cpu");
    ASSERT_TRUE(sim.ok()) << sim.status().message();
    sim.value()->step(0.0);
    const ocean::CascadeFrame& f = sim.value()->frame().cascades.front();
    const std::size_t texels = static_cast<std::size_t>(f.resolution) * f.resolution;
    for (std::size_t i = 0; i < texels; ++i) {
      const double h = f.displacement[3 * i + 1];
      const double nx = f.normal[3 * i], ny = f.normal[3 * i + 1], nz = f.normal[3 * i + 2];
      fft_h += h * h / (kSeeds * static_cast<double>(texels));
      fft_s += (nx * nx + nz * nz) / (ny * ny) / (kSeeds * static_cast<double>(texels));
    }
  }
  std::printf("simulated cascade 0 (%d seeds): height variance %.4f m², mean-square slope %.5f\n",
              kSeeds, fft_h, fft_s);
  // 4σ of the mean over the seeds; the 8-bit-free float normals add no bias worth a bound.
  const double seeds_sqrt = std::sqrt(static_cast<double>(kSeeds));
  std::printf("sampling spread over the seeds: height %.3f, slope %.3f\n",
              target.height_sampling_rel_std / seeds_sqrt,
              target.slope_sampling_rel_std / seeds_sqrt);
  EXPECT_NEAR(fft_h / target.height_variance_m2, 1.0,
              4.0 * target.height_sampling_rel_std / seeds_sqrt);
  EXPECT_NEAR(fft_s / target.slope_variance, 1.0, 4.0 * target.slope_sampling_rel_std / seeds_sqrt);
}

TEST(FarField, BadRangesAreRefused) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (const FarFieldRange r :
       {FarFieldRange{.near_m = 500.0, .far_m = 500.0},
        FarFieldRange{.near_m = 900.0, .far_m = 500.0},
        FarFieldRange{.near_m = -1.0, .far_m = 500.0}, FarFieldRange{.near_m = nan, .far_m = 500.0},
        FarFieldRange{.near_m = 100.0, .far_m = INFINITY}}) {
    const ocean::Status s = ocean::render::validate(r);
    EXPECT_FALSE(s.ok());
    EXPECT_EQ(s.message().find('\n'), std::string::npos);
  }
  EXPECT_TRUE(ocean::render::validate(FarFieldRange{}).ok());
}

// The map's window (R.13b-3, R.13b-2): for cameras anywhere, the disc of radius D_max about the
// camera lies inside the part of the window the map draws at full weight (kFarNoiseFadeTexels
// from the last texel centres), the origin is a whole number of snap steps, and a camera that
// moves by less than a texel without crossing a snap line keeps the origin exactly.
TEST(FarField, MapWindowHoldsTheRangeAndSnaps) {
  const FarFieldRange range{};
  for (int n : {128, 512, 4096}) {
    for (const std::array<double, 2> camera :
         {std::array<double, 2>{0.0, 0.0}, {123.4, -5678.9}, {1e7 + 0.3, -3e6 - 17.0}}) {
      auto window = ocean::render::far_noise_window(range, n, camera[0], camera[1]);
      ASSERT_TRUE(window.ok()) << window.status().message();
      const ocean::FarNoiseConfig& w = window.value();
      const double texel = w.size_m / n;
      const double snap = ocean::render::kFarNoiseSnapTexels * texel;
      for (std::size_t axis = 0; axis < 2; ++axis) {
        const double low = w.origin_m[axis] + ocean::render::kFarNoiseFadeTexels * texel;
        const double high = w.origin_m[axis] + (n - 1 - ocean::render::kFarNoiseFadeTexels) * texel;
        EXPECT_LE(low, camera[axis] - range.far_m) << n;
        EXPECT_GE(high, camera[axis] + range.far_m) << n;
        const double steps = w.origin_m[axis] / snap;
        EXPECT_NEAR(steps, std::round(steps), 1e-6 * std::abs(steps) + 1e-9);
      }
      // Less than a texel, away from the snap line the camera sits next to.
      const double inside = std::fmod(camera[0] - 0.5 * w.size_m - w.origin_m[0], snap);
      const double step = inside < 0.5 * snap ? 0.4 * texel : -0.4 * texel;
      EXPECT_EQ(ocean::render::far_noise_origin(w, camera[0] + step, camera[1] + step), w.origin_m);
    }
  }
  for (int bad : {0, 64, 127, 4097}) {
    auto window = ocean::render::far_noise_window(range, bad, 0.0, 0.0);
    ASSERT_FALSE(window.ok());
    EXPECT_EQ(window.status().message().find('\n'), std::string::npos);
  }
  EXPECT_FALSE(ocean::render::far_noise_window({.near_m = 1e5, .far_m = 5e5}, 512, 0.0, 0.0).ok());
}

// The renderer's analytic octaves (src/render/shaders/far_noise.h, the code its shaders run) on
// the lattice far_noise_lattice places at a frame's origin O and time t (R.13b) are the CPU
// reference far_field_noise(noise, O + xz, t) (R.13a) within the map's texel tolerance
// (tests/sim/far_noise_test.cpp: float rounding of the lattice coordinate times the noise's
// derivative bounds), far from the world's origin and three days into a simulation: the analytic
// noise moves exactly as the map does.
TEST(FarField, RendererOctavesAreTheMovingReference) {
  auto fitted = ocean::render::fit_far_field_noise(moderate_heights());
  ASSERT_TRUE(fitted.ok());
  const ocean::render::FarFieldNoise& noise = fitted.value();
  ocean::render::shader::FarFieldUniforms f{};
  f.cell_m = {static_cast<float>(noise.cell_m[0]), static_cast<float>(noise.cell_m[1]),
              static_cast<float>(noise.cell_m[2]), 0.0f};
  f.amplitude_m = {static_cast<float>(noise.amplitude_m[0]),
                   static_cast<float>(noise.amplitude_m[1]),
                   static_cast<float>(noise.amplitude_m[2]), 0.0f};
  for (const std::array<double, 3> case_ : {std::array<double, 3>{0.0, 0.0, 0.0},
                                            {4096.0, -8192.0, 37.5},
                                            {1.5e7, -3.25e6, 259200.0}}) {
    const double ox = case_[0], oz = case_[1], t = case_[2];
    std::array<ocean::render::shader::FarOctaveUniforms, 3> o{};
    for (int i = 0; i < 3; ++i) {
      const ocean::FarNoiseLattice l = ocean::far_noise_lattice(noise, i, ox, oz, t);
      o[static_cast<std::size_t>(i)] = {l.rest_u, l.rest_v, l.cells_u, l.cells_v};
    }
    double worst_h = 0.0, worst_s = 0.0, tol_h = 0.0, tol_s = 0.0;
    for (int i = 0; i < 3; ++i) {  // |xz| ≤ 3 km: the lattice coordinate is ≤ 1 + 3000/s_o
      const double du = 4.0 * std::ldexp(1.0, -24) * (1.0 + 3000.0 / noise.cell_m[i]);
      tol_h += noise.amplitude_m[i] * (15.0 * du + 1e-6);
      tol_s += noise.amplitude_m[i] / noise.cell_m[i] * (48.0 * du + 1e-5);
    }
    for (int k = 0; k < 400; ++k) {
      const float x = static_cast<float>(-3000.0 + 15.01 * k);
      const float z = static_cast<float>(2900.0 - 14.57 * k);
      float h = 0.0f, sx = 0.0f, sz = 0.0f;
      ocean::render::shader::far_field_noise(f, o[0], o[1], o[2], x, z, 1.0f, 1.0f, 1.0f, h, sx,
                                             sz);
      const ocean::render::FarFieldSample r =
          ocean::render::far_field_noise(noise, ox + x, oz + z, t);
      worst_h = std::max(worst_h, std::abs(h - r.height_m));
      worst_s = std::max({worst_s, std::abs(sx - r.slope_x), std::abs(sz - r.slope_z)});
    }
    EXPECT_LE(worst_h, tol_h) << "origin " << ox << ", " << oz << ", t = " << t;
    EXPECT_LE(worst_s, tol_s) << "origin " << ox << ", " << oz << ", t = " << t;
  }
}

}  // namespace
