// Height queries far from the world's origin: the same sea at x, z and at x, z offset by 10⁶ m
// and 10⁷ m (whole multiples of every cascade's period) — the displacement and the
// inverse-displacement query (M.7.6, M.7.7) agree within 1 mm, as docs/rendering.md R.16
// promises for the picture.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <vector>

#include "ocean/backends.hpp"
#include "ocean/sim.hpp"

namespace {

TEST(LargeWorld, HeightQueriesAgreeWithinAMillimetreFarFromTheOrigin) {
  ocean::SimulationConfig c;
  c.sea.wind_sea.spectrum.wind_speed_mps = 14.0;
  c.resolution = 64;
  c.cascade_patch_sizes_m = {400.0, 80.0, 16.0};  // each divides 10⁶ m
  c.choppiness = 1.0;
  auto made = ocean::make_simulator(c);
  ASSERT_TRUE(made.ok()) << made.status().message();
  auto& sim = *made.value();
  sim.step(4.0);
  std::vector<std::array<double, 2>> near;
  for (int i = 0; i < 64; ++i) near.push_back({-37.3 + 5.17 * i, 11.9 - 3.31 * i});
  std::vector<ocean::HeightSample> at_origin(near.size());
  sim.heights_at(near, at_origin);
  for (const double offset : {1e6, 1e7}) {
    std::vector<std::array<double, 2>> far = near;
    for (auto& p : far) p[0] += offset, p[1] -= offset;
    std::vector<ocean::HeightSample> there(far.size());
    sim.heights_at(far, there);
    double worst = 0.0;
    for (std::size_t i = 0; i < near.size(); ++i) {
      const auto d0 = sim.displacement_at(near[i][0], near[i][1]);
      const auto d1 = sim.displacement_at(far[i][0], far[i][1]);
      for (int k = 0; k < 3; ++k) worst = std::max(worst, std::abs(d0[k] - d1[k]));
      worst = std::max(worst, std::abs(at_origin[i].height_m - there[i].height_m));
      // The source point found is the same one, moved by the offset.
      worst = std::max(worst, std::abs(there[i].source_xz[0] - offset - at_origin[i].source_xz[0]));
      worst = std::max(worst, std::abs(there[i].source_xz[1] + offset - at_origin[i].source_xz[1]));
    }
    EXPECT_LT(worst, 1e-3) << "offset " << offset << " m";
  }
}

}  // namespace
