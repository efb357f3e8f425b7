// The waves shorter than the finest cascade drawn near the eye (lavapipe, validation layer on;
// docs/rendering.md R.62, docs/math.md M.9.4). Straight down over the moderate sea with pixels of
// 7.3 mm, the normals debug view's slopes with the short waves less those without them are the sum
// of sines of SurfaceDescription::short_waves at the pixels' points, each weighted by how well the
// pixel resolves it, as the CPU evaluates R.62 here from the plan.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include "ocean/plan.hpp"
#include "render/render_helpers.hpp"
#include "support/require_devices.hpp"

namespace ripples_render_test {

using namespace ocean::render;
namespace helpers = ocean::render::testing;
constexpr double kPi = std::numbers::pi;

#ifndef REQUIRE_DEVICE
#define REQUIRE_DEVICE()                                     \
  if (ocean::render::testing::graphics_context() == nullptr) \
  OCEAN_SKIP_OR_FAIL(                                        \
      "no Vulkan "                                           \
      "device")
#endif

ocean::SimulationConfig moderate() {
  ocean::SimulationConfig c;
  c.cascade_patch_sizes_m = {1000.0, 233.0, 57.0, 13.0};
  return c;
}

constexpr int kSide = 96;
// From 2 km up through a narrow lens: the square of 0.70 m it sees lies on a grid of 7.3 mm to
// within the waves' ±1.5 m of height over 2 km (0.3 mm at its edge), whatever the waves below.
constexpr double kHeight_m = 2000.0;
constexpr double kFovDeg = 0.0201;

// Camera at (x, 2 km, 0) looking straight down, square picture.
View straight_down(double x_m) {
  View v;
  v.camera = {.position_m = {x_m, kHeight_m, 0.0},
              .target_m = {x_m + 1e-4, -10.0, 0.0},
              .fov_y_rad = kFovDeg * kPi / 180.0,
              .aspect = 1.0,
              .near_m = 1000.0,
              .far_m = 4000.0};
  v.shading = sky_preset("clear").value();
  v.planet_radius_m = std::numeric_limits<double>::infinity();
  v.debug = DebugView::normals;
  return v;
}

// The drawn surface gradient per pixel from the normals view (0.5·N + 0.5 in rgb): (N_x, N_z)/N_y.
std::vector<std::array<double, 2>> drawn_slopes(Renderer& r, const View& v) {
  std::vector<float> hdr;
  EXPECT_TRUE(r.draw(v).ok());
  EXPECT_TRUE(r.read_hdr(hdr).ok());
  std::vector<std::array<double, 2>> out;
  for (std::size_t i = 0; i + 3 < hdr.size(); i += 4) {
    const double nx = 2.0 * hdr[i] - 1.0, ny = 2.0 * hdr[i + 1] - 1.0, nz = 2.0 * hdr[i + 2] - 1.0;
    out.push_back({nx / ny, nz / ny});
  }
  return out;
}

// Per pixel |s_with − s_without|: the short waves' own gradient (the slopes add before the normal
// is formed, ocean.frag).
std::vector<double> ripple_slopes(Renderer& r, View v) {
  v.shading.ripples = true;
  const auto with = drawn_slopes(r, v);
  v.shading.ripples = false;
  const auto without = drawn_slopes(r, v);
  std::vector<double> out;
  for (std::size_t i = 0; i < with.size() && i < without.size(); ++i)
    out.push_back(std::hypot(with[i][0] - without[i][0], with[i][1] - without[i][1]));
  return out;
}

// R.62 on the CPU at the pixels' points: a square of kSide² points f apart centred under the eye
// (f the footprint of a pixel on the plane), each wave weighted by w = clamp(2 − 2Δθ/π, 0, 1)
// with Δθ = f·max(|k_x|, |k_z|). The picture holds the same points up to the square's own
// symmetries (the image axes against the world's), which leave each point's |slope| as it is:
// the sorted magnitudes compare one to one.
struct Expected {
  std::vector<double> slopes;
  double resolved_variance = 0.0;  // Σ w²·(a·k)²/2
};
Expected expected_slopes(const std::vector<ocean::ShortWaveComponent>& waves, double time_s) {
  const double side_m = 2.0 * kHeight_m * std::tan(0.5 * kFovDeg * kPi / 180.0);
  const double f = side_m / kSide;
  Expected e;
  std::vector<double> weight(waves.size());
  for (std::size_t i = 0; i < waves.size(); ++i) {
    const double dtheta = f * std::max(std::abs(waves[i].kx_radpm), std::abs(waves[i].kz_radpm));
    weight[i] = std::clamp(2.0 - 2.0 * dtheta / kPi, 0.0, 1.0);
    e.resolved_variance += weight[i] * weight[i] * waves[i].slope_variance();
  }
  for (int row = 0; row < kSide; ++row)
    for (int col = 0; col < kSide; ++col) {
      const double x = (col + 0.5 - 0.5 * kSide) * f, z = (row + 0.5 - 0.5 * kSide) * f;
      double sx = 0.0, sz = 0.0;
      for (std::size_t i = 0; i < waves.size(); ++i) {
        const ocean::ShortWaveComponent& w = waves[i];
        const double k = std::hypot(w.kx_radpm, w.kz_radpm);
        const double s = weight[i] * w.amplitude_m * k *
                         std::sin(w.kx_radpm * x + w.kz_radpm * z - w.omega_radps * time_s +
                                  w.phase_rad);
        sx += s * w.kx_radpm / k;
        sz += s * w.kz_radpm / k;
      }
      e.slopes.push_back(std::hypot(sx, sz));
    }
  return e;
}

double mean_square(const std::vector<double>& v) {
  double sum = 0.0;
  for (double x : v) sum += x * x;
  return v.empty() ? 0.0 : sum / static_cast<double>(v.size());
}

// Straight down with a pixel 7.3 mm on the water, the picture draws the short waves from the
// finest cascade's 7 cm down to about 1.5 cm: its slopes are R.62's sum at the pixels' points
// (sorted magnitudes within 0.01: half-float normals, float phases, the chop's few per cent in the
// footprint), a third or more of the slope variance the cascades leave out. The same sea 10⁶ m
// from the origin draws the same statistics (phases taken at the camera in double precision,
// R.16). Calm water (the layer alone) has none.
TEST(Ripples, TheNearestWaterDrawsTheShortWavesItResolves) {
  REQUIRE_DEVICE();
  const ocean::SimulationConfig config = moderate();
  const ocean::SimulationPlan plan = ocean::SimulationPlan::make(config).value();
  const std::vector<ocean::ShortWaveComponent>& waves = plan.short_waves();
  ASSERT_EQ(waves.size(), 48u);
  auto rig = helpers::make_rig(helpers::graphics_context(), config, kSide, kSide);
  ASSERT_NE(rig, nullptr);
  const double time_s = rig->sim->frame().time_s;

  std::vector<double> drawn = ripple_slopes(*rig->renderer, straight_down(0.0));
  ASSERT_EQ(drawn.size(), static_cast<std::size_t>(kSide * kSide));
  Expected expected = expected_slopes(waves, time_s);
  std::sort(drawn.begin(), drawn.end());
  std::sort(expected.slopes.begin(), expected.slopes.end());
  double worst = 0.0;
  for (std::size_t i = 0; i < drawn.size(); ++i)
    worst = std::max(worst, std::abs(drawn[i] - expected.slopes[i]));
  const double unresolved = plan.unresolved_slope_variance()->total();
  std::printf(
      "pixels of 7.3 mm: drawn mean-square slope %.5f, R.62's %.5f (its weights' %.5f) of the "
      "%.5f the cascades leave out; sorted |slope| within %.4f\n",
      mean_square(drawn), mean_square(expected.slopes), expected.resolved_variance, unresolved,
      worst);
  EXPECT_LT(worst, 0.01);
  EXPECT_NEAR(mean_square(drawn), mean_square(expected.slopes), 0.03 * mean_square(expected.slopes));
  EXPECT_GT(expected.resolved_variance, unresolved / 3.0);
  EXPECT_LE(expected.resolved_variance, unresolved);

  // Far from the origin: other points of the same sea, the same statistics.
  const std::vector<double> far = ripple_slopes(*rig->renderer, straight_down(1e6 + 0.37));
  std::printf("10^6 m from the origin: mean-square slope %.5f\n", mean_square(far));
  EXPECT_NEAR(mean_square(far), expected.resolved_variance, 0.1 * expected.resolved_variance);

  rig->renderer->set_calm(true);
  const std::vector<double> calm = ripple_slopes(*rig->renderer, straight_down(0.0));
  EXPECT_LT(*std::max_element(calm.begin(), calm.end()), 1e-3);
}

}  // namespace ripples_render_test
