// The far field's CPU reference (ocean/far_field.hpp, docs/rendering.md R.13): VR-GIS FFT+Perlin's
// Hermite ratio (eq. 6) and its identities, the unit noise's moments against a direct
// measurement, the fitted noise's height variance and mean-square slope against both cascade 0's
// spectrum integral and the simulated cascade 0 itself, and bad ranges. No device needed.
#include "ocean/far_field.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "ocean/backends.hpp"

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

}  // namespace
