// The far field's noise map (SimulationConfig::far_noise, docs/rendering.md R.13a) on the CPU
// backend: every texel equals the analytic noise (ocean/far_noise.hpp) at its world point and time
// up to the float rounding of its lattice coordinate; the animated noise at t = 0 is the static
// noise the renderer draws; each octave is carried unchanged at its drift velocity, which is the
// band's mean phase velocity (between the deep-water phase speeds of the sub-band's edges, along
// the waves' mean direction); the map's height variance and mean-square slope equal the fitted
// band sums at every time; the map changes nothing else in the frame; bad maps are refused.
#include "ocean/far_noise.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <memory>
#include <utility>
#include <vector>

#include "ocean/backends/cpu.hpp"
#include "sim/far_noise_map.hpp"

namespace {

using ocean::FarFieldNoise;
using ocean::SimulationConfig;

// A small simulation (64² cascades) with a 64² map over a 3 km window off the origin.
SimulationConfig noise_small_config() {
  SimulationConfig c;
  c.resolution = 64;
  c.far_noise = {.resolution = 64, .origin_m = {-1234.5, 777.25}, .size_m = 3000.0};
  return c;
}

struct Stepped {
  std::unique_ptr<ocean::cpu::CpuBackend> backend;
  std::unique_ptr<ocean::TaskRunner> runner;
  ocean::Frame frame;
};
Stepped configure(const SimulationConfig& config, ocean::cpu::CpuOptions options = {}) {
  Stepped s{ocean::cpu::make_cpu_backend(options), ocean::make_tbb_runner(2), {}};
  const ocean::Status status = s.backend->configure(config, *s.runner);
  EXPECT_TRUE(status.ok()) << status.message();
  s.backend->allocate(s.frame);
  return s;
}

// Bounds on unit gradient noise and its derivatives over a cell (4 corners, unit gradients,
// offsets ≤ √2, the quintic fade f ≤ 1, f' ≤ 15/8, f'' ≤ 10/√3): |∇g| ≤ 4·(15/8·√2 + 1) < 15,
// |∇∇g| ≤ 4·(10/√3·√2 + 2·15/8) < 48.
constexpr double kGradientBound = 15.0, kCurvatureBound = 48.0;

// How far a texel may be from the analytic noise: its lattice coordinate origin + col·step is
// rounded (the rest of the origin, the step, the product and the sum: 4 roundings of at most
// 2^-24 of a value ≤ 1 + N·step each), moving the point by δu cells; height and gradient move by
// at most their derivative bounds times that, plus a few ulps of the sums themselves.
struct Tolerance {
  double height_m = 0.0, slope = 0.0;
};
Tolerance tolerance(const FarFieldNoise& noise, const ocean::FarNoiseConfig& map) {
  Tolerance t;
  for (int o = 0; o < 3; ++o) {
    const double step = map.size_m / map.resolution / noise.cell_m[o];
    const double du = 4.0 * std::ldexp(1.0, -24) * (1.0 + map.resolution * step);
    t.height_m += noise.amplitude_m[o] * (kGradientBound * du + 1e-6);
    t.slope += noise.amplitude_m[o] / noise.cell_m[o] * (kCurvatureBound * du + 1e-5);
  }
  return t;
}

TEST(FarNoiseMap, EveryTexelIsTheAnalyticNoiseAtItsPointAndTime) {
  const SimulationConfig config = noise_small_config();
  Stepped s = configure(config);
  auto noise = ocean::fit_far_field_noise(config);
  ASSERT_TRUE(noise.ok()) << noise.status().message();
  const Tolerance tol = tolerance(noise.value(), config.far_noise);
  const int n = config.far_noise.resolution;
  const double spacing = config.far_noise.size_m / n;
  // Three days: the octaves have travelled hundreds of kilometres, thousands of cells.
  for (double t : {0.0, 37.5, 259200.0}) {
    s.backend->step(t, s.frame);
    ASSERT_EQ(s.frame.far_noise.resolution, n);
    ASSERT_EQ(s.frame.far_noise.height_slope.size(), std::size_t{3} * n * n);
    double worst_h = 0.0, worst_s = 0.0, rms = 0.0;
    for (int row = 0; row < n; ++row)
      for (int col = 0; col < n; ++col) {
        const ocean::FarFieldSample a =
            ocean::far_field_noise(noise.value(), config.far_noise.origin_m[0] + col * spacing,
                                   config.far_noise.origin_m[1] + row * spacing, t);
        const float* m = &s.frame.far_noise.height_slope[3 * (std::size_t(row) * n + col)];
        worst_h = std::max(worst_h, std::abs(m[0] - a.height_m));
        worst_s = std::max({worst_s, std::abs(m[1] - a.slope_x), std::abs(m[2] - a.slope_z)});
        rms += a.height_m * a.height_m;
      }
    EXPECT_LE(worst_h, tol.height_m) << "t = " << t;
    EXPECT_LE(worst_s, tol.slope) << "t = " << t;
    EXPECT_GT(std::sqrt(rms / (n * n)), 100.0 * tol.height_m) << "a flat map proves nothing";
  }
}

// Simulator::set_far_noise_origin moves the window from the next step on: the frame says where
// its map lies, and every texel is the analytic noise at its point of the new window.
TEST(FarNoiseMap, MovingTheOriginMovesTheWindow) {
  const SimulationConfig config = noise_small_config();
  auto sim = ocean::Simulator::make(config, ocean::cpu::make_cpu_backend({}));
  ASSERT_TRUE(sim.ok()) << sim.status().message();
  auto noise = ocean::fit_far_field_noise(config);
  ASSERT_TRUE(noise.ok());
  const std::array<double, 2> moved = {98765.5, -4321.25};
  sim.value()->set_far_noise_origin(moved);
  EXPECT_EQ(sim.value()->config().far_noise.origin_m, moved);
  const double t = 12.5;
  sim.value()->step(t);
  const ocean::FarNoiseFrame& map = sim.value()->frame().far_noise;
  ASSERT_EQ(map.origin_m, moved);
  ocean::FarNoiseConfig window = config.far_noise;
  window.origin_m = moved;
  const Tolerance tol = tolerance(noise.value(), window);
  const int n = window.resolution;
  const double spacing = window.size_m / n;
  double worst_h = 0.0, worst_s = 0.0;
  for (int row = 0; row < n; row += 7)
    for (int col = 0; col < n; col += 5) {
      const ocean::FarFieldSample a = ocean::far_field_noise(
          noise.value(), moved[0] + col * spacing, moved[1] + row * spacing, t);
      const float* m = &map.height_slope[3 * (std::size_t(row) * n + col)];
      worst_h = std::max(worst_h, std::abs(m[0] - a.height_m));
      worst_s = std::max({worst_s, std::abs(m[1] - a.slope_x), std::abs(m[2] - a.slope_z)});
    }
  EXPECT_LE(worst_h, tol.height_m);
  EXPECT_LE(worst_s, tol.slope);
}

// The CPU task carries each octave's corner gradients along a row instead of hashing four per
// texel: the same arithmetic on the same gradients, so every texel has the bits of
// far_noise_texel (the per-texel function the Vulkan kernel runs), for steps below and above one
// cell per texel.
TEST(FarNoiseMap, CarriedGradientsGiveTheBitsOfThePerTexelFunction) {
  auto noise = ocean::fit_far_field_noise(noise_small_config());
  ASSERT_TRUE(noise.ok());
  for (const double size_m : {3000.0, 40000.0}) {
    const ocean::FarNoiseConfig map{
        .resolution = 48, .origin_m = {-777.0, 123.0}, .size_m = size_m};
    const auto p = ocean::far_noise_map::params(noise.value(), map, 1234.5);
    std::vector<float> rows(3 * 48 * 48);
    ocean::far_noise_map::fill_rows(p, 0, 48, rows.data());
    for (std::uint32_t row = 0; row < 48; ++row)
      for (std::uint32_t col = 0; col < 48; ++col) {
        float t[3];
        ocean::noise::far_noise_texel(p, col, row, t[0], t[1], t[2]);
        ASSERT_EQ(std::memcmp(t, &rows[3 * (row * 48 + col)], sizeof(t)), 0)
            << "texel " << col << ", " << row << ", window " << size_m;
      }
  }
}

TEST(FarNoiseMap, AtTimeZeroTheNoiseIsTheRenderersStaticNoise) {
  auto noise = ocean::fit_far_field_noise(noise_small_config());
  ASSERT_TRUE(noise.ok());
  const ocean::FarNoiseConfig one_cell{.resolution = 1, .size_m = 1.0};
  const Tolerance tol = tolerance(noise.value(), one_cell);
  for (int i = 0; i < 200; ++i) {
    const double x = -3000.0 + 31.7 * i, z = 1500.0 - 17.3 * i;
    const ocean::FarFieldSample a = ocean::far_field_noise(noise.value(), x, z);
    const ocean::FarFieldSample b = ocean::far_field_noise(noise.value(), x, z, 0.0);
    // The static noise reads x/s in float (|x/s| < 2^7: 2^-17 cells) where the animated one
    // splits it in double: the same point to a few ulps of the coordinate.
    EXPECT_NEAR(a.height_m, b.height_m, 4.0 * tol.height_m);
    EXPECT_NEAR(a.slope_x, b.slope_x, 4.0 * tol.slope);
    EXPECT_NEAR(a.slope_z, b.slope_z, 4.0 * tol.slope);
  }
}

TEST(FarNoiseMap, EachOctaveTravelsAtTheBandsMeanPhaseVelocity) {
  const SimulationConfig config = noise_small_config();
  auto fitted = ocean::fit_far_field_noise(config);
  ASSERT_TRUE(fitted.ok());
  const FarFieldNoise& noise = fitted.value();
  const ocean::SeaState sea = ocean::SeaState::make(config.sea).value();
  const auto band = ocean::cascade_bands(config).front();
  const double g = ocean::kDefaultGravity;
  for (int o = 0; o < 3; ++o) {
    const auto& v = noise.velocity_mps[o];
    // Waves towards +x, spread symmetrically about it on a grid symmetric in kz: no drift in z.
    EXPECT_NEAR(v[1], 0.0, 1e-9 * v[0]) << "octave " << o;
    // A mean of c(k)·cos θ over the band: below the fastest wave's speed, the deep-water phase
    // speed √(g/k) at the band's lowest wavenumber 2π/L, and above a third of the slowest's
    // (Donelan–Banner spreading keeps most energy within ±60° of the mean direction).
    const double k_lo = std::max(band[0], 2.0 * ocean::kPi / config.cascade_patch_sizes_m[0]);
    EXPECT_LT(v[0], std::sqrt(g / k_lo)) << "octave " << o;
    EXPECT_GT(v[0], sea.dispersion().phase_velocity(band[1]) / 3.0) << "octave " << o;
    // The octave alone is carried unchanged: h(x + v·t, t) = h(x, 0).
    FarFieldNoise one = noise;
    for (int p = 0; p < 3; ++p)
      if (p != o) one.amplitude_m[p] = 0.0;
    const Tolerance tol = tolerance(one, {.resolution = 1, .size_m = 1.0});
    for (double t : {10.0, 1000.0}) {
      for (int i = 0; i < 20; ++i) {
        const double x = 53.0 * i, z = -29.0 * i;
        const auto a = ocean::far_field_noise(one, x, z, 0.0);
        const auto b = ocean::far_field_noise(one, x + v[0] * t, z + v[1] * t, t);
        EXPECT_NEAR(a.height_m, b.height_m, 4.0 * tol.height_m);
        EXPECT_NEAR(a.slope_x, b.slope_x, 4.0 * tol.slope);
      }
    }
  }
}

// Over a window of 256 × 256 octave-0 cells the measured moments of one noise field lie within
// 3 % of their expectations (the static field's measurement, tests/render/far_field_test.cpp);
// translation keeps a field's statistics, so every time must too.
TEST(FarNoiseMap, MomentsEqualTheBandsAtEveryTime) {
  SimulationConfig config = noise_small_config();
  auto fitted = ocean::fit_far_field_noise(config);
  ASSERT_TRUE(fitted.ok());
  const ocean::BandStatistics target = fitted.value().target;
  config.far_noise = {.resolution = 256,
                      .origin_m = {5000.0, -7000.0},
                      .size_m = 256.0 * fitted.value().cell_m[0] * 1.013};
  Stepped s = configure(config);
  for (double t : {0.0, 600.0, 86400.0}) {
    s.backend->step(t, s.frame);
    const auto& m = s.frame.far_noise.height_slope;
    double h1 = 0.0, h2 = 0.0, s2 = 0.0;
    const double count = static_cast<double>(m.size() / 3);
    for (std::size_t i = 0; i < m.size(); i += 3) {
      h1 += m[i];
      h2 += double(m[i]) * m[i];
      s2 += double(m[i + 1]) * m[i + 1] + double(m[i + 2]) * m[i + 2];
    }
    const double var = h2 / count - (h1 / count) * (h1 / count);
    EXPECT_NEAR(var / target.height_variance_m2, 1.0, 0.03) << "t = " << t;
    EXPECT_NEAR(s2 / count / target.slope_variance, 1.0, 0.03) << "t = " << t;
  }
}

// The map is a task of its own in each shape of the frame: beside the cascade groups' chains
// (central differences), beside the whole cascade stages (analytic normals), and after them on
// the scalar reference pipeline; none changes a bit of the cascades.
class FarNoiseFrame
    : public ::testing::TestWithParam<std::pair<ocean::NormalMethod, ocean::cpu::CpuPipeline>> {};

TEST_P(FarNoiseFrame, ChangesNothingElseInTheFrame) {
  SimulationConfig with = noise_small_config();
  with.normals = GetParam().first;
  SimulationConfig without = with;
  without.far_noise.resolution = 0;
  const ocean::cpu::CpuOptions options{.pipeline = GetParam().second};
  Stepped a = configure(with, options), b = configure(without, options);
  for (double t : {0.0, 0.5}) {
    a.backend->step(t, a.frame);
    b.backend->step(t, b.frame);
  }
  Stepped fused = configure(with);
  fused.backend->step(0.5, fused.frame);
  EXPECT_EQ(
      std::memcmp(fused.frame.far_noise.height_slope.data(), a.frame.far_noise.height_slope.data(),
                  a.frame.far_noise.height_slope.size() * sizeof(float)),
      0)
      << "the map depends on nothing but its parameters and the time";
  EXPECT_TRUE(b.frame.far_noise.height_slope.empty());
  ASSERT_EQ(a.frame.cascades.size(), b.frame.cascades.size());
  for (std::size_t c = 0; c < a.frame.cascades.size(); ++c) {
    const auto same = [](const auto& x, const auto& y) {
      return x.size() == y.size() && std::memcmp(x.data(), y.data(), x.size() * sizeof(x[0])) == 0;
    };
    const ocean::CascadeFrame &x = a.frame.cascades[c], &y = b.frame.cascades[c];
    EXPECT_TRUE(same(x.displacement, y.displacement)) << c;
    EXPECT_TRUE(same(x.displacement_half, y.displacement_half)) << c;
    EXPECT_TRUE(same(x.normal, y.normal)) << c;
    EXPECT_TRUE(same(x.foam, y.foam)) << c;
    EXPECT_TRUE(same(x.packed_mips, y.packed_mips)) << c;
  }
  // The noise alone: the same map as the full step's.
  ocean::Frame alone;
  a.backend->allocate(alone);
  a.backend->step_far_noise(0.5, alone);
  EXPECT_EQ(std::memcmp(alone.far_noise.height_slope.data(), a.frame.far_noise.height_slope.data(),
                        alone.far_noise.height_slope.size() * sizeof(float)),
            0);
}

INSTANTIATE_TEST_SUITE_P(Shapes, FarNoiseFrame,
                         ::testing::Values(std::pair{ocean::NormalMethod::central_difference,
                                                     ocean::cpu::CpuPipeline::fused_simd},
                                           std::pair{ocean::NormalMethod::analytic,
                                                     ocean::cpu::CpuPipeline::fused_simd},
                                           std::pair{ocean::NormalMethod::central_difference,
                                                     ocean::cpu::CpuPipeline::scalar_reference}));

TEST(FarNoiseMap, BadMapsAreRefused) {
  SimulationConfig c = noise_small_config();
  c.far_noise.resolution = 8;
  EXPECT_EQ(ocean::validate(c).code(), ocean::ErrorCode::invalid_argument);
  EXPECT_NE(ocean::validate(c).message().find("far_noise.resolution"), std::string::npos);
  c = noise_small_config();
  c.far_noise.size_m = 0.0;
  EXPECT_EQ(ocean::validate(c).code(), ocean::ErrorCode::invalid_argument);
  c = noise_small_config();
  c.far_noise.origin_m[1] = std::nan("");
  EXPECT_FALSE(ocean::validate(c).ok());
  c = noise_small_config();
  c.far_noise.resolution = 0;  // off: any window
  c.far_noise.size_m = 1e6;
  EXPECT_TRUE(ocean::validate(c).ok());
}

}  // namespace
