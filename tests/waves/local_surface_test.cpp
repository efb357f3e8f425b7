// The local surface (docs/math.md M.7.9): the sea's cascades and the local layer summed on the
// layer's grid before the normal, Jacobian and foam. Each cell is the queried surface at its
// centre; J is eq. 48 of the sum and the foam its ramp and accumulation (M.7.4); a cosine
// waveform on a sea whose bands only shade has the normal of the cosine, A·k·sin(kx).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>

#include "ocean/backends.hpp"
#include "ocean/sim.hpp"
#include "ocean/waves.hpp"

namespace {

using ocean::waves::LayerParams;

std::unique_ptr<ocean::Simulator> sea(std::vector<ocean::BandRole> roles = {}) {
  ocean::SimulationConfig c;
  c.sea.wind_sea.spectrum = {
      .model = ocean::SpectrumModel::jonswap, .wind_speed_mps = 14.0, .fetch_m = 8e4};
  c.resolution = 64;
  c.cascade_patch_sizes_m = {300.0, 71.0};
  c.choppiness = 1.5;
  c.foam.source = ocean::FoamSource::ramp;  // the checks below recompute the ramp
  c.band_roles = std::move(roles);
  auto sim = ocean::make_simulator(c);
  EXPECT_TRUE(sim.ok()) << sim.status().message();
  return std::move(sim).value();
}

std::shared_ptr<const ocean::waves::LocalLayer> layer(LayerParams p) {
  auto made = ocean::waves::LocalLayer::make(std::move(p));
  EXPECT_TRUE(made.ok()) << made.status().message();
  return std::move(made).value();
}

float ramp(const ocean::FoamParams& f, float j) {
  return std::clamp(
      static_cast<float>((f.jacobian_start - j) / (f.jacobian_start - f.jacobian_full)), 0.0f,
      1.0f);
}

// A wake crossing an 80 m square of 64² cells, its peak height `peak_m`.
LayerParams surface_wake_params(double peak_m) {
  LayerParams p;
  p.area = {.origin_m = {-40.0, -40.0}, .size_m = 80.0, .resolution = 64};
  p.wakes.push_back({.x_m = 20.0,
                     .heading_deg = 200.0,
                     .speed_mps = 4.0,
                     .hull_length_m = 10.0,
                     .peak_height_m = peak_m});
  return p;
}

TEST(LocalSurface, IsTheQueriedSurfaceWithTheJacobianAndFoamOfTheSum) {
  auto sim = sea();
  LayerParams p = surface_wake_params(0.8);
  sim->set_local_layer(layer(p));
  sim->step(1.0);
  const ocean::LocalSurfaceFrame& s = sim->frame().local;
  const int n = p.area.resolution;
  ASSERT_EQ(s.resolution, n);
  ASSERT_EQ(s.displacement.size(), 3u * n * n);
  const double spacing = p.area.size_m / n;
  const ocean::FoamParams& foam = sim->config().foam;
  int foaming = 0;
  for (int row = 1; row + 1 < n; row += 3) {
    for (int col = 1; col + 1 < n; col += 3) {
      const auto i = static_cast<std::size_t>(row * n + col);
      const auto centre = ocean::waves::cell_centre(p.area, col, row);
      const auto d = sim->displacement_at(centre[0], centre[1]);  // sea + layer, as queried
      for (std::size_t k = 0; k < 3; ++k)
        ASSERT_EQ(s.displacement[3 * i + k], static_cast<float>(d[k])) << col << ", " << row;
      // Eq. 48 from central differences of the summed displacement.
      const auto at = [&](int c, int r, int k) {
        return static_cast<double>(
            s.displacement[3 * static_cast<std::size_t>(r * n + c) + static_cast<std::size_t>(k)]);
      };
      const double dxx = (at(col + 1, row, 0) - at(col - 1, row, 0)) / (2 * spacing);
      const double dzz = (at(col, row + 1, 2) - at(col, row - 1, 2)) / (2 * spacing);
      const double dxz = (at(col, row + 1, 0) - at(col, row - 1, 0)) / (2 * spacing);
      const double dzx = (at(col + 1, row, 2) - at(col - 1, row, 2)) / (2 * spacing);
      const double j = (1 + dxx) * (1 + dzz) - dxz * dzx;
      EXPECT_NEAR(s.jacobian[i], j, 1e-5 * (1 + std::abs(j))) << col << ", " << row;
      EXPECT_NEAR(s.foam[i], ramp(foam, s.jacobian[i]), 1e-6f);  // the first frame: the ramp
      foaming += s.foam[i] > 0.0f;
    }
  }
  EXPECT_GT(foaming, 0);  // a choppy 14 m/s sea with a wake on it folds somewhere
  // The next frame accumulates (M.7.4): max(foam − decay·Δt/max(now, ½), now).
  const std::vector<float> before = s.foam;
  sim->step(1.25);
  const ocean::LocalSurfaceFrame& next = sim->frame().local;
  const float decay = static_cast<float>(foam.decay_per_s * 0.25);
  for (std::size_t i = 0; i < next.foam.size(); ++i) {
    const float now = ramp(foam, next.jacobian[i]);
    const float expected =
        std::clamp(std::max(before[i] - decay / std::max(now, 0.5f), now), 0.0f, 1.0f);
    ASSERT_NEAR(next.foam[i], expected, 1e-6f) << i;
  }
}

TEST(LocalSurface, ACosineWaveformOnAShadingSeaHasTheCosinesNormal) {
  auto sim = sea({ocean::BandRole::shade, ocean::BandRole::shade});  // the sea does not move
  auto map = std::make_shared<ocean::waves::HeightMap>();
  map->rows = map->cols = 256;
  map->values.resize(256 * 256);
  constexpr double kPeriods = 4.0, kSize = 100.0, kA = 0.5;
  for (int r = 0; r < 256; ++r)
    for (int c = 0; c < 256; ++c)
      map->values[static_cast<std::size_t>(r * 256 + c)] =
          static_cast<float>(std::cos(2 * M_PI * kPeriods * (c + 0.5) / 256));
  LayerParams p;
  p.area = {.origin_m = {-40.0, -40.0}, .size_m = 80.0, .resolution = 128};
  p.waveforms.push_back({.map = map, .size_m = kSize, .amplitude_m = kA});
  sim->set_local_layer(layer(p));
  sim->step(0.5);
  const ocean::LocalSurfaceFrame& s = sim->frame().local;
  const double k = 2 * M_PI * kPeriods / kSize;  // h = A·cos(kx) (the map's sample c at x_c)
  double largest = 0.0;
  for (int row = 20; row < 108; row += 5) {
    for (int col = 20; col < 108; ++col) {  // inside the layer's soft edge (8 m)
      const auto i = static_cast<std::size_t>(row * 128 + col);
      const double x = ocean::waves::cell_centre(p.area, col, row)[0];
      const double slope = kA * k * std::sin(k * x);  // −∂h/∂x
      ASSERT_NEAR(s.normal[3 * i], slope / std::sqrt(1 + slope * slope), 0.01 * kA * k) << x;
      ASSERT_NEAR(s.normal[3 * i + 2], 0.0, 1e-6);
      ASSERT_EQ(s.jacobian[i], 1.0f);  // a waveform moves the surface up and down only
      ASSERT_EQ(s.foam[i], 0.0f);
      largest = std::max(largest, std::abs(static_cast<double>(s.displacement[3 * i + 1])));
    }
  }
  EXPECT_NEAR(largest, kA, 0.01 * kA);
}

TEST(LocalSurface, IsEmptyWithoutALayerAndFollowsTheLayerAcrossReconfigure) {
  auto sim = sea();
  sim->step(0.0);
  EXPECT_EQ(sim->frame().local.resolution, 0);
  EXPECT_TRUE(sim->frame().local.displacement.empty());
  LayerParams p;
  p.area = {.origin_m = {0.0, 0.0}, .size_m = 50.0, .resolution = 32};
  sim->set_local_layer(layer(p));
  ASSERT_TRUE(sim->reconfigure(sim->config()).ok());
  sim->step(0.1);
  EXPECT_EQ(sim->frame().local.resolution, 32);
  EXPECT_EQ(sim->frame().local.foam.size(), 32u * 32u);
  sim->set_local_layer(nullptr);
  sim->step(0.2);
  EXPECT_TRUE(sim->frame().local.displacement.empty());
}

// The sea alone beside the sum (M.7.10): a wake's layer carried beside the sum, and the sea's
// normal and foam equal to those of a simulator whose layer is the same wake at zero height
// (its sum is the sea alone, computed independently), over several accumulating steps.
TEST(LocalSurface, CarriesTheLayerAndTheSeaAloneBesideTheSum) {
  auto with = sea(), without = sea();
  LayerParams p = surface_wake_params(1.2);
  const auto wake = layer(p);
  with->set_local_layer(wake);
  p.wakes[0].peak_height_m = 0.0;
  without->set_local_layer(layer(p));
  for (const double t : {1.0, 1.1, 1.2, 1.3}) with->step(t), without->step(t);
  const ocean::LocalSurfaceFrame& a = with->frame().local;
  const ocean::LocalSurfaceFrame& b = without->frame().local;
  const std::size_t cells = static_cast<std::size_t>(a.resolution) * a.resolution;
  ASSERT_EQ(a.layer_displacement.size(), 3 * cells);
  ASSERT_EQ(a.sea_normal.size(), 3 * cells);
  ASSERT_EQ(a.sea_foam.size(), cells);
  double worst_layer = 0.0, worst_normal = 0.0, worst_foam = 0.0, layer_tilt = 0.0;
  for (std::size_t i = 0; i < cells; ++i) {
    const auto [x, z] = ocean::waves::cell_centre(p.area, static_cast<int>(i % a.resolution),
                                                  static_cast<int>(i / a.resolution));
    const std::array<double, 3> d = wake->displacement_at(x, z, 1.3);
    for (std::size_t k = 0; k < 3; ++k) {
      worst_layer = std::max(worst_layer, std::abs(a.layer_displacement[3 * i + k] - d[k]));
      worst_normal = std::max(worst_normal, std::abs(static_cast<double>(a.sea_normal[3 * i + k]) -
                                                     b.normal[3 * i + k]));
      layer_tilt = std::max(
          layer_tilt, std::abs(static_cast<double>(a.normal[3 * i + k]) - a.sea_normal[3 * i + k]));
    }
    worst_foam = std::max(worst_foam, std::abs(static_cast<double>(a.sea_foam[i]) - b.foam[i]));
    EXPECT_EQ(b.sea_normal[3 * i + 1], b.normal[3 * i + 1]);  // no layer: the sum is the sea
    EXPECT_EQ(b.sea_foam[i], b.foam[i]);
  }
  // Float rounding of the sum less the layer (heights of order 1 m, cells 1.25 m apart).
  EXPECT_LE(worst_layer, 1e-6);
  EXPECT_LE(worst_normal, 1e-4);
  EXPECT_LE(worst_foam, 1e-3);
  EXPECT_GT(layer_tilt, 0.05);  // the wake does tilt the sum's normal away from the sea's
}

}  // namespace

// A layer that replaces one on the same grid (a driven wake remade at a waypoint) carries the
// composited surface's foam on: the frames are those of a layer never replaced. One on a new grid
// restarts it from the ramp (M.7.4's first frame).
TEST(LocalSurface, ALayerReplacedOnTheSameGridKeepsItsFoam) {
  const LayerParams p = surface_wake_params(0.8);
  auto kept = sea();
  kept->set_local_layer(layer(p));
  auto replaced = sea();
  replaced->set_local_layer(layer(p));
  for (const double t : {1.0, 1.25}) {
    kept->step(t);
    replaced->step(t);
  }
  replaced->set_local_layer(layer(p));  // a new layer object on the same grid
  kept->step(1.5);
  replaced->step(1.5);
  const ocean::LocalSurfaceFrame& a = kept->frame().local;
  const ocean::LocalSurfaceFrame& b = replaced->frame().local;
  const ocean::FoamParams& foam = kept->config().foam;
  int accumulated = 0;  // cells whose foam is more than this frame's ramp: what a restart loses
  for (std::size_t i = 0; i < a.foam.size(); ++i) {
    ASSERT_EQ(a.foam[i], b.foam[i]) << i;
    ASSERT_EQ(a.sea_foam[i], b.sea_foam[i]) << i;
    accumulated += a.foam[i] > ramp(foam, a.jacobian[i]) + 1e-3f;
  }
  EXPECT_GT(accumulated, 0);

  LayerParams moved = p;
  moved.area.origin_m[0] += moved.area.size_m / moved.area.resolution;  // one cell along x
  replaced->set_local_layer(layer(moved));
  replaced->step(1.75);
  const ocean::LocalSurfaceFrame& c = replaced->frame().local;
  for (std::size_t i = 0; i < c.foam.size(); ++i)
    ASSERT_NEAR(c.foam[i], ramp(foam, c.jacobian[i]), 1e-6f) << i;
}
