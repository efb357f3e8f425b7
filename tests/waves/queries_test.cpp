// Height queries see the local layer: the inverse-displacement query of a simulator with a layer
// lands on sea + layer, a waveform composited into the layer is found at its place on top of the
// sea, and a calm sea's queries see the layer alone.
#include <gtest/gtest.h>

#include <cmath>

#include "ocean/backends.hpp"
#include "ocean/sim.hpp"
#include "ocean/waves.hpp"

namespace {

using ocean::waves::LayerParams;

std::unique_ptr<ocean::Simulator> queries_sea() {
  ocean::SimulationConfig c;
  c.sea.wind_sea.spectrum = {
      .model = ocean::SpectrumModel::jonswap, .wind_speed_mps = 9.0, .fetch_m = 8e4};
  c.resolution = 64;
  c.cascade_patch_sizes_m = {300.0, 71.0};
  c.choppiness = 0.9;
  auto sim = ocean::make_simulator(c);
  EXPECT_TRUE(sim.ok()) << sim.status().message();
  sim.value()->step(3.0);
  return std::move(sim).value();
}

std::shared_ptr<const ocean::waves::LocalLayer> queries_layer(LayerParams p) {
  auto made = ocean::waves::LocalLayer::make(std::move(p));
  EXPECT_TRUE(made.ok()) << made.status().message();
  return std::move(made).value();
}

LayerParams wake_params() {
  LayerParams p;
  p.area = {.origin_m = {-60.0, -60.0}, .size_m = 120.0, .resolution = 256};
  p.wakes.push_back({.x_m = 30.0,
                     .heading_deg = 20.0,
                     .speed_mps = 3.0,
                     .hull_length_m = 8.0,
                     .peak_height_m = 0.4});
  p.wakes[0].x_m = 30.0 - 3.0 * 3.0 * std::cos(20.0 * M_PI / 180);  // at (30, z) when t = 3 s
  p.wakes[0].z_m = -3.0 * 3.0 * std::sin(20.0 * M_PI / 180);
  return p;
}

TEST(LocalLayerQueries, InverseDisplacementLandsOnSeaPlusLayer) {
  auto sim = queries_sea();
  const auto before = sim->displacement_at(10.0, 2.0);
  sim->set_local_layer(queries_layer(wake_params()));
  const auto with = sim->displacement_at(10.0, 2.0);
  const auto local = sim->local_layer()->displacement_at(10.0, 2.0, 3.0);
  for (int k = 0; k < 3; ++k) EXPECT_DOUBLE_EQ(with[k], before[k] + local[k]);
  std::vector<std::array<double, 2>> targets;
  std::vector<double> expected;
  double largest_local = 0.0;
  for (double x = -40.0; x <= 25.0; x += 3.7) {
    for (double z = -30.0; z <= 30.0; z += 4.9) {
      const auto d = sim->displacement_at(x, z);  // sea + layer at the source point
      targets.push_back({x + d[0], z + d[2]});
      expected.push_back(d[1]);
      largest_local =
          std::max(largest_local, std::abs(sim->local_layer()->displacement_at(x, z, 3.0)[1]));
    }
  }
  EXPECT_GT(largest_local, 0.1);  // the wake is there to be found
  std::vector<ocean::HeightSample> out(targets.size());
  sim->heights_at(targets, out);
  for (std::size_t q = 0; q < out.size(); ++q) {
    EXPECT_NEAR(out[q].height_m, expected[q], 1e-4) << q;
    EXPECT_LT(out[q].iterations, 40);
  }
}

TEST(LocalLayerQueries, WaveformIsFoundAtItsPlaceOnTopOfTheSea) {
  auto sim = queries_sea();
  auto flat = std::make_shared<ocean::waves::HeightMap>();
  flat->rows = flat->cols = 4;
  flat->values.assign(16, 1.0f);
  LayerParams p;
  p.area = {.origin_m = {-50.0, -50.0}, .size_m = 100.0, .resolution = 64};
  p.waveforms.push_back({.map = flat, .x_m = 5.0, .z_m = -8.0, .size_m = 20.0, .amplitude_m = 0.3});
  const std::vector<std::array<double, 2>> at = {{5.0, -8.0}, {12.0, -1.0}, {-3.0, -15.0}};
  std::vector<ocean::HeightSample> bare(at.size()), composited(at.size());
  sim->heights_at(at, bare);
  sim->set_local_layer(queries_layer(p));
  sim->heights_at(at, composited);
  for (std::size_t q = 0; q < at.size(); ++q) {
    // A waveform has no horizontal displacement: the same source point, 0.3 m higher.
    EXPECT_NEAR(composited[q].height_m, bare[q].height_m + 0.3, 1e-12) << q;
  }
}

TEST(LocalLayerQueries, CalmSeaSeesTheLayerAlone) {
  const auto only = queries_layer(wake_params());
  std::vector<std::array<double, 2>> targets;
  std::vector<double> expected;
  for (double x = -40.0; x <= 25.0; x += 6.1) {
    const auto d = only->displacement_at(x, 3.0, 3.0);
    targets.push_back({x + d[0], 3.0 + d[2]});
    expected.push_back(d[1]);
  }
  std::vector<ocean::HeightSample> out(targets.size());
  ocean::heights_at(*only, 3.0, targets, out);
  for (std::size_t q = 0; q < out.size(); ++q) EXPECT_NEAR(out[q].height_m, expected[q], 1e-6);
}

}  // namespace
