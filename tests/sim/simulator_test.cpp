// The simulator end to end on the CPU backend: looping, exact phase after days, determinism
// across thread counts, band-split cascades, double buffering, height queries, validation.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "ocean/backends.hpp"

namespace {

ocean::SimulationConfig small_config() {
  ocean::SimulationConfig c;
  c.sea.wind_sea = {
      .spectrum = {.model = ocean::SpectrumModel::jonswap, .wind_speed_mps = 9.0, .fetch_m = 8e4},
      .spreading = {.model = ocean::SpreadingModel::donelan_banner},
      .direction_rad = 0.3};
  c.resolution = 64;
  c.cascade_patch_sizes_m = {300.0, 71.0};
  c.choppiness = 0.9;
  c.loop_period_s = 100.0;
  c.seed = 5;
  return c;
}

std::unique_ptr<ocean::Simulator> make(const ocean::SimulationConfig& c,
                                       std::shared_ptr<ocean::TaskRunner> runner = nullptr) {
  auto sim = ocean::make_simulator(c, "cpu", std::move(runner));
  EXPECT_TRUE(sim.ok()) << sim.status().message();
  return std::move(sim).value();
}

float max_abs_difference(std::span<const float> a, std::span<const float> b) {
  float m = 0.0f;
  for (std::size_t i = 0; i < a.size(); ++i) m = std::max(m, std::abs(a[i] - b[i]));
  return m;
}

float max_abs(std::span<const float> a) {
  float m = 0.0f;
  for (float v : a) m = std::max(m, std::abs(v));
  return m;
}

TEST(Simulator, LoopRepeatsAfterPeriodEvenAfterDays) {
  auto sim = make(small_config());
  sim->step(12.5);
  const auto first = sim->frame().cascades[0].displacement;
  const float scale = max_abs(first);
  ASSERT_GT(scale, 0.1f);
  sim->step(12.5 + 100.0);
  EXPECT_LT(max_abs_difference(sim->frame().cascades[0].displacement, first), 1e-6f * scale);
  sim->step(12.5 + 100.0 * 2592.0);  // 3 days later: the phase is still exact
  EXPECT_LT(max_abs_difference(sim->frame().cascades[0].displacement, first), 1e-6f * scale);
  sim->step(12.5 + 50.0);  // but half a period later it is a different sea
  EXPECT_GT(max_abs_difference(sim->frame().cascades[0].displacement, first), 0.1f * scale);
}

// The CPU backend keeps each cascade group's chain of stages on one thread when there are no
// more threads than groups, and spreads every chain's stages over the threads otherwise: 2
// cascades (one group) and 4 (two groups) on 1, 2 and 3 threads take both ways, on oneTBB and
// on the ready runner (the frame loops' pool), stepped and kicked.
TEST(Simulator, BitIdenticalForAnyThreadCount) {
  for (const std::vector<double>& sizes :
       {std::vector<double>{300.0, 71.0}, std::vector<double>{300.0, 71.0, 17.0, 4.0}}) {
    SCOPED_TRACE(std::to_string(sizes.size()) + " cascades");
    ocean::SimulationConfig c = small_config();
    c.cascade_patch_sizes_m = sizes;
    auto serial = make(c, std::shared_ptr<ocean::TaskRunner>(ocean::make_serial_runner()));
    auto two = make(c, std::shared_ptr<ocean::TaskRunner>(ocean::make_tbb_runner(2)));
    auto three = make(c, std::shared_ptr<ocean::TaskRunner>(ocean::make_tbb_runner(3)));
    auto all = make(c);
    auto ready2 = make(c, std::shared_ptr<ocean::TaskRunner>(
                              ocean::make_ready_runner({.threads = 2, .spin_us = 100.0})));
    auto ready3 = make(c, std::shared_ptr<ocean::TaskRunner>(
                              ocean::make_ready_runner({.threads = 3, .spin_us = 0.0})));
    for (auto* sim : {serial.get(), two.get(), three.get(), all.get(), ready2.get()}) {
      sim->step(3.0);
      sim->step(3.5);
    }
    ready3->kick(3.0);
    ready3->kick(3.5);
    ready3->wait();
    for (std::size_t k = 0; k < c.cascade_patch_sizes_m.size(); ++k) {
      const auto& a = serial->frame().cascades[k];
      for (auto* sim : {two.get(), three.get(), all.get(), ready2.get(), ready3.get()}) {
        const auto& b = sim->frame().cascades[k];
        EXPECT_EQ(
            std::memcmp(a.displacement.data(), b.displacement.data(), a.displacement.size() * 4),
            0);
        EXPECT_EQ(std::memcmp(a.normal.data(), b.normal.data(), a.normal.size() * 4), 0);
        EXPECT_EQ(std::memcmp(a.foam.data(), b.foam.data(), a.foam.size() * 4), 0);
        EXPECT_EQ(a.packed_mips, b.packed_mips);
        EXPECT_EQ(a.displacement_half, b.displacement_half);
      }
    }
  }
}

// Each wave vector belongs to one cascade: the bands are contiguous and disjoint, and the
// variance of the summed cascades is the spectrum's m0 (within what the grids resolve), while
// overlapping (unsplit) cascades would count the shared band twice.
TEST(Simulator, CascadeBandsPartitionTheVariance) {
  ocean::SimulationConfig c = small_config();
  c.resolution = 128;
  c.cascade_patch_sizes_m = {1200.0, 270.0, 61.0};
  const auto bands = ocean::cascade_bands(c);
  ASSERT_EQ(bands.size(), 3u);
  EXPECT_EQ(bands[0][0], 0.0);
  EXPECT_EQ(bands[0][1], bands[1][0]);
  EXPECT_EQ(bands[1][1], bands[2][0]);
  EXPECT_TRUE(std::isinf(bands[2][1]));
  const ocean::SeaState sea = ocean::SeaState::make(c.sea).value();
  const auto grid_variance = [&](double patch, double k_min, double k_max) {
    const double dk = 2 * ocean::kPi / patch;
    double sum = 0.0;
    for (int r = 1; r < c.resolution; ++r) {  // the Nyquist row/column (index 0) is empty
      for (int col = 1; col < c.resolution; ++col) {
        const double kx = dk * (col - c.resolution / 2), kz = dk * (r - c.resolution / 2);
        const double k = std::hypot(kx, kz);
        if (k >= k_min && k < k_max) sum += sea.wave_vector_spectrum(kx, kz) * dk * dk;
      }
    }
    return sum;
  };
  double split = 0.0, overlapping = 0.0;
  for (std::size_t i = 0; i < 3; ++i) {
    split += grid_variance(c.cascade_patch_sizes_m[i], bands[i][0], bands[i][1]);
    overlapping += grid_variance(c.cascade_patch_sizes_m[i], 0.0, INFINITY);
  }
  EXPECT_NEAR(split / sea.variance_m2(), 1.0, 0.03);
  EXPECT_GT(overlapping / sea.variance_m2(), 1.5);
  // The simulator's summed surface realises that variance (averaged over seeds).
  double realised = 0.0;
  constexpr int kSeeds = 12;
  for (int seed = 1; seed <= kSeeds; ++seed) {
    c.seed = static_cast<std::uint64_t>(seed);
    auto sim = make(c);
    sim->step(0.0);
    double sum2 = 0.0;
    const int n = 128;
    for (int r = 0; r < n; ++r) {
      for (int col = 0; col < n; ++col) {
        // Sample the summed surface on the largest patch's grid.
        const double x = col * 1200.0 / n, z = r * 1200.0 / n;
        const double h = sim->displacement_at(x, z)[1];
        sum2 += h * h;
      }
    }
    realised += sum2 / (n * n) / kSeeds;
  }
  EXPECT_NEAR(realised / split, 1.0, 0.1);
}

TEST(Simulator, KickComputesInTheBackground) {
  auto sim = make(small_config());
  sim->step(1.0);
  const auto front = sim->frame().cascades[0].displacement;
  sim->kick(2.0);
  // The published frame is untouched while the next one is computed.
  EXPECT_EQ(sim->frame().time_s, 1.0);
  EXPECT_EQ(sim->frame().cascades[0].displacement, front);
  sim->wait();
  EXPECT_EQ(sim->frame().time_s, 2.0);
  EXPECT_NE(sim->frame().cascades[0].displacement, front);
  sim->wait();  // nothing pending: a no-op
  EXPECT_EQ(sim->frame().time_s, 2.0);
}

// The height query inverts the horizontal displacement: a surface point that started at a
// texel p and was displaced to p + D_xz(p) reports h(p).
// An engine's own job system: a runner that counts what the simulator asks of it and runs
// everything on the calling thread. kick/wait go through its async slot (no other threads), and
// the frames equal those of step().
class CountingRunner final : public ocean::TaskRunner {
 public:
  struct Counts {
    int loops = 0, slots = 0, kicks = 0, waits = 0;
  };
  void parallel_for(std::size_t n, std::size_t /*grain*/,
                    ocean::FunctionRef<void(std::size_t, std::size_t)> body) override {
    ++counts.loops;
    if (n > 0) body(0, n);
  }
  [[nodiscard]] int concurrency() const override { return 1; }
  [[nodiscard]] std::unique_ptr<ocean::AsyncSlot> make_async_slot() override {
    ++counts.slots;
    return std::make_unique<Slot>(counts);
  }
  Counts counts;

 private:
  class Slot final : public ocean::AsyncSlot {
   public:
    explicit Slot(Counts& counts) : counts_(counts) {}
    void kick(ocean::FunctionRef<void()> job) override {
      ++counts_.kicks;
      job();
    }
    void wait() override { ++counts_.waits; }

   private:
    Counts& counts_;
  };
};

TEST(Simulator, KickAndWaitRunOnTheCallersRunner) {
  const ocean::SimulationConfig c = small_config();
  auto runner = std::make_shared<CountingRunner>();
  auto kicked = make(c, runner);
  auto stepped = make(c, std::shared_ptr<ocean::TaskRunner>(ocean::make_serial_runner()));
  EXPECT_EQ(runner->counts.slots, 1);
  for (double t : {1.0, 1.5, 2.0}) {
    const int loops = runner->counts.loops;
    kicked->kick(t);
    EXPECT_GT(runner->counts.loops, loops);  // the step's loops ran on this runner
    kicked->wait();
    stepped->step(t);
    for (std::size_t k = 0; k < c.cascade_patch_sizes_m.size(); ++k) {
      const auto& a = kicked->frame().cascades[k];
      const auto& b = stepped->frame().cascades[k];
      EXPECT_EQ(a.displacement, b.displacement);
      EXPECT_EQ(a.displacement_half, b.displacement_half);
      EXPECT_EQ(a.normal, b.normal);
      EXPECT_EQ(a.jacobian, b.jacobian);
      EXPECT_EQ(a.foam, b.foam);
      EXPECT_EQ(a.packed_mips, b.packed_mips);
    }
  }
  EXPECT_EQ(runner->counts.kicks, 3);
  EXPECT_GE(runner->counts.waits, 3);
  EXPECT_EQ(runner->counts.slots, 1);  // made once, at set-up
}

TEST(Simulator, HeightQueriesInvertTheDisplacement) {
  ocean::SimulationConfig c = small_config();
  c.cascade_patch_sizes_m = {250.0};
  auto sim = make(c);
  sim->step(4.0);
  const auto& f = sim->frame().cascades[0];
  std::vector<std::array<double, 2>> targets;
  std::vector<double> expected;
  for (int i = 0; i < 64 * 64; i += 97) {
    const double x = (i % 64) * 250.0 / 64 + 1000.0, z = (i / 64) * 250.0 / 64 - 500.0;
    const auto idx = static_cast<std::size_t>(i);
    targets.push_back({x + f.displacement[3 * idx], z + f.displacement[3 * idx + 2]});
    expected.push_back(f.displacement[3 * idx + 1]);
  }
  std::vector<ocean::HeightSample> out(targets.size());
  sim->heights_at(targets, out);
  for (std::size_t q = 0; q < out.size(); ++q) {
    EXPECT_NEAR(out[q].height_m, expected[q], 1e-4) << q;
    EXPECT_LT(out[q].iterations, 40);
  }
}

TEST(Simulator, DisplacementSamplingWrapsAndInterpolates) {
  ocean::SimulationConfig c = small_config();
  c.cascade_patch_sizes_m = {64.0};
  auto sim = make(c);
  sim->step(0.5);
  const auto& f = sim->frame().cascades[0];
  const auto texel = [&](int col, int row) {
    return double(f.displacement[3 * static_cast<std::size_t>(row * 64 + col) + 1]);
  };
  EXPECT_NEAR(sim->displacement_at(3.0, 5.0)[1], texel(3, 5), 1e-6);
  EXPECT_NEAR(sim->displacement_at(3.0 + 64.0 * 7, 5.0 - 64.0 * 3)[1], texel(3, 5), 1e-6);
  EXPECT_NEAR(sim->displacement_at(3.5, 5.0)[1], 0.5 * (texel(3, 5) + texel(4, 5)), 1e-6);
  EXPECT_NEAR(sim->displacement_at(63.5, 0.0)[1], 0.5 * (texel(63, 0) + texel(0, 0)), 1e-6);
}

// ---- surface queries: height, normal and particle velocity (M.7.11) ----

ocean::SimulationConfig velocity_config() {
  ocean::SimulationConfig c = small_config();
  c.outputs.velocity = true;
  return c;
}

// max over texels and components of |V − (D(t + δ) − D(t − δ))/(2δ)| for every cascade.
double velocity_vs_difference(ocean::Simulator& sim, double t, double delta, double* largest) {
  sim.step(t - delta);
  const ocean::Frame before = sim.detach(sim.frame());
  sim.step(t + delta);
  const ocean::Frame after = sim.detach(sim.frame());
  sim.step(t);
  double error = 0.0;
  *largest = 0.0;
  for (std::size_t c = 0; c < sim.frame().cascades.size(); ++c) {
    const auto& v = sim.frame().cascades[c].velocity;
    const auto& d0 = before.cascades[c].displacement;
    const auto& d1 = after.cascades[c].displacement;
    EXPECT_EQ(v.size(), d0.size());
    for (std::size_t i = 0; i < v.size(); ++i) {
      const double difference = (double(d1[i]) - double(d0[i])) / (2.0 * delta);
      error = std::max(error, std::abs(double(v[i]) - difference));
      *largest = std::max(*largest, std::abs(double(v[i])));
    }
  }
  return error;
}

// The velocity is the time derivative of the displacement. For one wave component a·sin(ωt + φ)
// the central difference over ±δ is exactly a·ω·cos(ωt + φ)·sin(ωδ)/(ωδ): its error is the
// velocity times 1 − sinc(ωδ) ≈ (ωδ)²/6, O(δ²). Halving δ must then divide the error by 4 (a wrong
// sign, factor or phase in V would leave an error that does not shrink); the float rounding of
// the displacement (~1e-6 m, its error/(2δ) ~ 1e-5 m/s at δ = 0.05 s) stays far below the
// truncation at these δ, so the ratio is bounded by 0.3 rather than 0.25. At δ = 0.1 s the
// fastest resolved wave (k = π·64/71 rad/m, ω = √(gk) = 5.3 rad/s) has (ωδ)²/6 = 4.6 % of its
// own velocity, the energetic ones (ω ≈ 1 rad/s) 0.2 %: the error is below 5 % of the largest
// velocity.
TEST(Simulator, VelocityIsTheTimeDerivativeOfTheDisplacement) {
  auto sim = make(velocity_config());
  double largest = 0.0, largest_half = 0.0;
  const double error = velocity_vs_difference(*sim, 7.3, 0.1, &largest);
  const double error_half = velocity_vs_difference(*sim, 7.3, 0.05, &largest_half);
  std::printf(
      "velocity vs central difference: max |V| = %.4g m/s, error %.3g (δ = 0.1 s), "
      "%.3g (δ = 0.05 s), ratio %.3f\n",
      largest, error, error_half, error_half / error);
  ASSERT_GT(largest, 0.1);
  EXPECT_EQ(largest, largest_half);  // the same frame at t
  EXPECT_LT(error, 0.05 * largest);
  EXPECT_LT(error_half, 0.3 * error);
}

TEST(Simulator, VelocityIsOffByDefaultAndNaNInQueries) {
  auto sim = make(small_config());
  sim->step(1.0);
  EXPECT_TRUE(sim->frame().cascades[0].velocity.empty());
  EXPECT_FALSE(sim->has_velocity());
  const std::array<double, 2> p{3.0, 4.0};
  ocean::SurfaceSample s;
  sim->surface_at(std::span(&p, 1), std::span(&s, 1));
  EXPECT_TRUE(std::isnan(s.velocity[0]) && std::isnan(s.velocity[1]) && std::isnan(s.velocity[2]));
  EXPECT_TRUE(std::isfinite(s.height_m));
}

std::vector<std::array<double, 2>> surface_points() {
  std::vector<std::array<double, 2>> xz;
  for (int i = 0; i < 40; ++i) xz.push_back({-83.1 + 11.7 * i, 41.3 - 7.9 * i});
  return xz;
}

// The normal is (−∂η/∂x, 1, −∂η/∂z) normalised, η the height heights_at returns. The reference
// gradient is a difference of heights_at over ±ε, ε = 1e-3 m. Inside a texel cell η is smooth
// (the inverse of a bilinear map), curvature κ ≲ slope/cell ≈ 1/1.1 m⁻¹: the central difference
// errs by ~κ·ε²; a one-sided one (used when ±ε crosses a cell edge, where the slope jumps) by
// ~κ·ε ≈ 1e-3. The inverse stops within 1e-6 m of the point (M.7.7), a height error of at most
// slope × 1e-6 m, i.e. ≲ 1e-6/ε = 1e-3 in the gradient. A normal component moves by at most as
// much as the gradient: 2e-3 bounds the sum.
TEST(Simulator, SurfaceNormalIsTheHeightGradient) {
  auto sim = make(velocity_config());
  sim->step(7.3);
  const auto xz = surface_points();
  std::vector<ocean::SurfaceSample> surface(xz.size());
  std::vector<ocean::HeightSample> heights(xz.size());
  sim->surface_at(xz, surface);
  sim->heights_at(xz, heights);
  constexpr double eps = 1e-3;
  double worst = 0.0, steepest = 0.0;
  for (std::size_t q = 0; q < xz.size(); ++q) {
    EXPECT_EQ(surface[q].height_m, heights[q].height_m) << q;  // bit-identical
    const auto eta = [&](double dx, double dz) {
      const std::array<double, 2> p{xz[q][0] + dx, xz[q][1] + dz};
      ocean::HeightSample h;
      sim->heights_at(std::span(&p, 1), std::span(&h, 1));
      return h.height_m;
    };
    const double e0 = heights[q].height_m;
    const double ex[3] = {(eta(eps, 0) - eta(-eps, 0)) / (2 * eps), (eta(eps, 0) - e0) / eps,
                          (e0 - eta(-eps, 0)) / eps};
    const double ez[3] = {(eta(0, eps) - eta(0, -eps)) / (2 * eps), (eta(0, eps) - e0) / eps,
                          (e0 - eta(0, -eps)) / eps};
    const auto& n = surface[q].normal;
    EXPECT_NEAR(n[0] * n[0] + n[1] * n[1] + n[2] * n[2], 1.0, 1e-12);
    ASSERT_GT(n[1], 0.0);
    double best = 1e9;
    for (double gx : ex) {
      for (double gz : ez) {
        const double length = std::sqrt(gx * gx + 1.0 + gz * gz);
        const double err = std::max({std::abs(n[0] + gx / length), std::abs(n[1] - 1.0 / length),
                                     std::abs(n[2] + gz / length)});
        best = std::min(best, err);
      }
    }
    worst = std::max(worst, best);
    steepest = std::max(steepest, std::hypot(n[0], n[2]));
  }
  std::printf("normal vs height gradient: largest error %.3g, steepest sin(tilt) %.3f\n", worst,
              steepest);
  EXPECT_GT(steepest, 0.02);  // a sea with slopes, not a flat one
  EXPECT_LT(worst, 2e-3);
}

// The kinematic surface condition: the surface moves with its particles, w = ∂η/∂t + u·∂η/∂x +
// v·∂η/∂z at a fixed (x, z). For the bilinear surface the identity is exact (η(x, t) = h(p, t)
// with p + D_xz(p, t) = x, and the velocity is ∂D/∂t at the texels, interpolated alike), so the
// residual is the central difference of η in time, O(δ²) as in
// VelocityIsTheTimeDerivativeOfTheDisplacement (halving δ divides it by ≈ 4), plus the inverse's
// tolerance, ≲ slope × 1e-6 m/δ ≈ 1e-5 m/s.
TEST(Simulator, KinematicSurfaceConditionHolds) {
  auto sim = make(velocity_config());
  const auto xz = surface_points();
  const double t = 7.3;
  const auto residual = [&](double delta, double* largest_w) {
    std::vector<ocean::HeightSample> before(xz.size()), after(xz.size());
    std::vector<ocean::SurfaceSample> now(xz.size());
    sim->step(t - delta);
    sim->heights_at(xz, before);
    sim->step(t + delta);
    sim->heights_at(xz, after);
    sim->step(t);
    sim->surface_at(xz, now);
    double worst = 0.0;
    *largest_w = 0.0;
    for (std::size_t q = 0; q < xz.size(); ++q) {
      const auto& n = now[q].normal;
      const auto& v = now[q].velocity;
      const double deta_dt = (after[q].height_m - before[q].height_m) / (2 * delta);
      const double w = deta_dt + v[0] * (-n[0] / n[1]) + v[2] * (-n[2] / n[1]);
      worst = std::max(worst, std::abs(v[1] - w));
      *largest_w = std::max(*largest_w, std::abs(v[1]));
    }
    return worst;
  };
  double w1 = 0.0, w2 = 0.0;
  const double r1 = residual(0.1, &w1);
  const double r2 = residual(0.05, &w2);
  std::printf(
      "kinematic condition: max |w| = %.4g m/s, residual %.3g (δ = 0.1 s), %.3g "
      "(δ = 0.05 s), ratio %.3f\n",
      w1, r1, r2, r2 / r1);
  ASSERT_GT(w1, 0.05);
  EXPECT_LT(r1, 0.05 * w1);
  EXPECT_LT(r2, 0.3 * r1 + 2e-5);
}

TEST(Simulator, ShadeOnlyBandHasNoVelocity) {
  ocean::SimulationConfig c = velocity_config();
  c.band_roles = {ocean::BandRole::both, ocean::BandRole::shade};
  auto sim = make(c);
  sim->step(2.0);
  EXPECT_GT(max_abs(sim->frame().cascades[0].velocity), 0.01f);
  EXPECT_EQ(max_abs(sim->frame().cascades[1].velocity), 0.0f);
}

TEST(Simulator, ValidatesConfiguration) {
  ocean::SimulationConfig c = small_config();
  c.resolution = 100;
  EXPECT_FALSE(ocean::make_simulator(c).ok());
  c = small_config();
  c.cascade_patch_sizes_m = {50.0, 80.0};
  EXPECT_NE(ocean::make_simulator(c).status().message().find("largest patch first"),
            std::string::npos);
  c = small_config();
  c.cascade_patch_sizes_m = {0.0};
  EXPECT_FALSE(ocean::make_simulator(c).ok());
  c = small_config();
  c.choppiness = std::nan("");
  EXPECT_FALSE(ocean::make_simulator(c).ok());
  c = small_config();
  c.sea.wind_sea.spectrum.fetch_m = 0.0;
  EXPECT_NE(ocean::make_simulator(c).status().message().find("fetch_m = 0"), std::string::npos);
}

// With a loop period T every ω is quantised down to a multiple of 2π/T (M.2.4): below
// T_min = 2π/ω(2π/L0) the longest waves get ω' = 0 and stand still. small_config's cascade 0 is
// 300 m in deep water, where ω² = g·k (Lamb 1932, §228): T_min = 2π/√(g·2π/300) = 13.86 s.
TEST(Simulator, LoopPeriodThatFreezesTheLongestWavesIsRejected) {
  ocean::SimulationConfig c = small_config();
  const double shortest = ocean::shortest_loop_period_s(c).value();
  const double expected = 2.0 * ocean::kPi / std::sqrt(9.81 * 2.0 * ocean::kPi / 300.0);
  EXPECT_NEAR(shortest, expected, 1e-14 * expected);
  // The wave vector (m, n) = (1, 0) of cascade 0, at grid index row N/2, column N/2 + 1.
  const std::size_t longest = 32 * 64 + 33;
  const ocean::SeaState sea = ocean::SeaState::make(c.sea).value();
  const auto omega_of_longest = [&](double period) {
    c.loop_period_s = period;
    return ocean::make_initial_spectrum(sea, ocean::cascade_spectrum_params(c, 0))
        .value()
        .omega[longest];
  };
  // At T_min the longest wave moves (one turn per loop) and the configuration is valid ...
  EXPECT_NEAR(omega_of_longest(shortest), 2.0 * ocean::kPi / shortest, 1e-6);
  EXPECT_TRUE(ocean::validate(c).ok());
  // ... one ulp below it stands still, and the configuration is refused, naming T_min.
  const double below = std::nextafter(shortest, 0.0);
  EXPECT_EQ(omega_of_longest(below), 0.0f);
  for (double period : {below, 10.0, 1e-3}) {
    c.loop_period_s = period;
    const ocean::Status s = ocean::validate(c);
    EXPECT_EQ(s.message(), "loop_period_s = " + ocean::format_number(period) +
                               " is too short: the longest waves (300 m) would stand still; must "
                               "be 0 (no loop) or in [" +
                               ocean::format_number(shortest) + ", 1e+06]");
    EXPECT_EQ(ocean::make_simulator(c).status().message(), s.message());
  }
  c.loop_period_s = 0.0;  // no loop: nothing is quantised
  EXPECT_TRUE(ocean::validate(c).ok());
}

TEST(Backends, UnavailableBackendsSaySo) {
  // vulkan depends on the build and the machine; cuda too, but neither CI nor this test's usual
  // machines have an NVIDIA driver: built without CUDA, or built with it and no device.
  const auto cuda = ocean::make_backend("cuda");
  ASSERT_FALSE(cuda.ok());
  EXPECT_EQ(cuda.status().code(), ocean::ErrorCode::unsupported);
  const std::string why = cuda.status().message();
  EXPECT_TRUE(why.find("built without") != std::string::npos || why.starts_with("no CUDA device: "))
      << why;
  EXPECT_EQ(ocean::make_backend("metal").status().code(), ocean::ErrorCode::invalid_argument);
  EXPECT_TRUE(ocean::make_backend("cpu").ok());
}

TEST(Backends, UnknownBackendIsEchoedOnOneLine) {
  EXPECT_EQ(ocean::make_backend("cpu\n").status().message(),
            "backend = 'cpu\\n' is unknown: must be one of cpu, vulkan, cuda");
}

}  // namespace
