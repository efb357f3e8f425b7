// Floating bodies against physics: Archimedes' draught in calm water (statically exact, and
// reached within 1 % by a dropped box), heave in a long wave against the linear mass–spring–
// damper response of the same hydrostatics (B.7), energy bounded over long runs (symplectic
// Euler), and a body on the simulator's own surface following the height at its centre.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <numbers>
#include <vector>

#include "ocean/backends.hpp"
#include "ocean/bodies.hpp"
#include "ocean/waves.hpp"

namespace {

using namespace ocean::bodies;
constexpr double kPi = std::numbers::pi;

// A flat box (2 × 0.5 × 2 m) of density 500 kg/m³: metacentrically stable (BM = b²/12d =
// 1.37 m > BG = 0.13 m), Archimedes' draught d = (500/1025)·0.5 m.
constexpr double kSide = 2.0, kHeight = 0.5, kDensity = 500.0;
const Water kWater{};
double archimedes_draught() { return kDensity / kWater.density_kgpm3 * kHeight; }
// The body's centre height at which its bottom is at depth d.
double centre_at_draught(double d) { return kHeight / 2 - d; }

BodyParams box(DragParams drag = {}) {
  auto p = solid_body(box_hull({kSide, kHeight, kSide}, 4).value(), kDensity, drag);
  EXPECT_TRUE(p.ok()) << p.status().message();
  return p.value();
}

// The surface of a calm sea through the library's inverse-displacement query: a local layer with
// nothing in it.
SurfaceQuery calm_layer_surface(std::shared_ptr<const ocean::waves::LocalLayer>& keep) {
  keep = ocean::waves::LocalLayer::make({}).value();
  const ocean::waves::LocalLayer* layer = keep.get();
  return [layer](std::span<const std::array<double, 2>> xz, std::span<ocean::HeightSample> out) {
    ocean::heights_at(*layer, 0.0, xz, out);
  };
}

TEST(Buoyancy, ArchimedesDraughtBalancesTheWeightExactly) {
  for (double heading : {0.0, 30.0}) {
    const BodyState at_rest{.position_m = {5.0, centre_at_draught(archimedes_draught()), -3.0},
                            .orientation = orientation_from_heading(heading)};
    auto body = FloatingBody::make(box(), at_rest).value();
    const Forces f = body.evaluate(calm_surface());
    const double weight = body.params().mass_kg * kWater.gravity_mps2;
    EXPECT_NEAR(f.force_n[1] / weight, 0.0, 1e-12) << heading;
    EXPECT_NEAR(f.submerged_volume_m3, kSide * kSide * archimedes_draught(), 1e-12);
    EXPECT_NEAR(f.wetted_area_m2, kSide * kSide + 4 * kSide * archimedes_draught(), 1e-12);
    for (double t : f.torque_nm) EXPECT_NEAR(t / (weight * kSide), 0.0, 1e-12);
  }
}

TEST(Buoyancy, DroppedBoxSettlesAtArchimedesDraught) {
  std::shared_ptr<const ocean::waves::LocalLayer> layer;
  const SurfaceQuery surface = calm_layer_surface(layer);
  auto body = FloatingBody::make(box(), {.position_m = {0.0, 0.6, 0.0}}).value();
  for (int i = 0; i < 40 * 60; ++i) ASSERT_TRUE(body.step(surface, 1.0 / 60).ok());
  const double draught = kHeight / 2 - body.state().position_m[1];
  EXPECT_NEAR(draught / archimedes_draught(), 1.0, 0.01) << draught;
  EXPECT_LT(std::abs(body.state().velocity_mps[1]), 1e-3);
}

// A long Airy wave η = a·cos(kx − ωt) travelling towards +x, deep water.
struct LongWave {
  double amplitude_m = 0.1, period_s = 8.0;
  [[nodiscard]] double omega() const { return 2 * kPi / period_s; }
  [[nodiscard]] double k() const { return omega() * omega() / kWater.gravity_mps2; }
  [[nodiscard]] double height(double x, double t) const {
    return amplitude_m * std::cos(k() * x - omega() * t);
  }
};

// Least-squares amplitude of e^{−iωt} in samples s(t_j) over whole periods: 2/N·Σ s·e^{iωt}.
std::complex<double> phasor(const std::vector<double>& s, const std::vector<double>& t, double w) {
  std::complex<double> sum = 0.0;
  for (std::size_t j = 0; j < s.size(); ++j)
    sum += s[j] * std::exp(std::complex<double>(0, w * t[j]));
  return 2.0 * sum / static_cast<double>(s.size());
}

TEST(Buoyancy, HeaveFollowsALongWaveAsTheLinearResponsePredicts) {
  // Linear drag only, so the heave is the linear oscillator m·ÿ + c·ẏ + k·y = k·η (B.7) with
  // k = ρgA_w (wall-sided box) and c = ρ·A·linear_mps (the bottom face): the response to
  // η = a·cos ωt is H = k/(k − mω² − icω) (for the e^{−iωt} convention), |H| = 1.015, arg H =
  // 2.3° of lag for this box in an 8 s wave (λ = 100 m ≫ 2 m: a small body).
  const LongWave wave;
  const double dt = 1.0 / 60;
  auto body =
      FloatingBody::make(box({.linear_mps = 0.5, .quadratic = 0.0}),
                         {.position_m = {0.0, centre_at_draught(archimedes_draught()), 0.0}})
          .value();
  double t = 0.0;
  const SurfaceQuery surface = [&](std::span<const std::array<double, 2>> xz,
                                   std::span<ocean::HeightSample> out) {
    for (std::size_t i = 0; i < xz.size(); ++i) out[i].height_m = wave.height(xz[i][0], t);
  };
  std::vector<double> heave, eta, times;
  const int steps_per_period = static_cast<int>(std::lround(wave.period_s / dt));
  for (int i = 0; i < 12 * steps_per_period; ++i) {
    if (i >= 4 * steps_per_period) {  // after the transient (ζ ≈ 0.16 at 1 s natural period)
      heave.push_back(body.state().position_m[1] - centre_at_draught(archimedes_draught()));
      eta.push_back(wave.height(body.state().position_m[0], t));
      times.push_back(t);
    }
    ASSERT_TRUE(body.step(surface, dt).ok());
    t += dt;
  }
  const double m = body.params().mass_kg, w = wave.omega();
  const double k = kWater.density_kgpm3 * kWater.gravity_mps2 * kSide * kSide;
  const double c = kWater.density_kgpm3 * kSide * kSide * 0.5;
  const std::complex<double> expected = k / std::complex<double>(k - m * w * w, -c * w);
  const std::complex<double> measured = phasor(heave, times, w) / phasor(eta, times, w);
  EXPECT_NEAR(std::abs(measured) / std::abs(expected), 1.0, 0.01)
      << std::abs(measured) << " vs " << std::abs(expected);
  EXPECT_NEAR(std::arg(measured) * 180 / kPi, std::arg(expected) * 180 / kPi, 0.5);
}

TEST(Buoyancy, HeaveEnergyStaysBoundedWithoutDrag) {
  // Calm water, no drag: E = ½mv² + ½k(y − y0)² of a wall-sided box. Symplectic Euler keeps a
  // modified energy exactly, so E oscillates by at most ωdt/(2 − ωdt) of itself (6.3 rad/s
  // natural frequency at dt = 0.01 s: 3.3 %) and never drifts.
  auto body =
      FloatingBody::make(box({.linear_mps = 0.0, .quadratic = 0.0}),
                         {.position_m = {0.0, centre_at_draught(archimedes_draught()) + 0.1, 0.0}})
          .value();
  const double k = kWater.density_kgpm3 * kWater.gravity_mps2 * kSide * kSide;
  const double m = body.params().mass_kg, dt = 0.01;
  const auto energy = [&] {
    const double y = body.state().position_m[1] - centre_at_draught(archimedes_draught());
    const double v = body.state().velocity_mps[1];
    return 0.5 * m * v * v + 0.5 * k * y * y;
  };
  const double e0 = energy(), bound = std::sqrt(k / m) * dt / (2 - std::sqrt(k / m) * dt);
  for (int i = 0; i < 10000; ++i) {
    ASSERT_TRUE(body.step(calm_surface(), dt).ok());
    ASSERT_NEAR(energy() / e0, 1.0, 1.05 * bound) << "step " << i;
  }
}

TEST(Buoyancy, LongRunInWavesDoesNotBlowUp) {
  // A boat, tilted and spinning at the start, two and a half minutes in a steep long wave with the
  // default drag: its heave stays within the wave's reach and its rotation bounded.
  const LongWave wave{.amplitude_m = 1.0, .period_s = 7.0};
  auto params = solid_body(boat_hull(8.0, 3.0, 1.2).value(), 350.0).value();
  BodyState start{.position_m = {0.0, 0.0, 0.0}, .angular_velocity_radps = {0.5, 0.2, 0.1}};
  start.orientation = {std::cos(0.1), std::sin(0.1), 0.0, 0.0};  // 11.5° of roll
  auto body = FloatingBody::make(params, start).value();
  double t = 0.0;
  const SurfaceQuery surface = [&](std::span<const std::array<double, 2>> xz,
                                   std::span<ocean::HeightSample> out) {
    for (std::size_t i = 0; i < xz.size(); ++i) out[i].height_m = wave.height(xz[i][0], t);
  };
  double max_omega = 0.0;
  for (int i = 0; i < 150 * 60; ++i) {
    ASSERT_TRUE(body.step(surface, 1.0 / 60).ok()) << i;
    t += 1.0 / 60;
    ASSERT_LT(std::abs(body.state().position_m[1]), 2.0 * wave.amplitude_m + 1.2) << t;
    const auto& w = body.state().angular_velocity_radps;
    if (t > 60.0)
      max_omega = std::max(max_omega, std::sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]));
  }
  // The wave's largest slope ak = 0.08 turns the boat at most by about ak·ω ≈ 0.07 rad/s.
  EXPECT_LT(max_omega, 0.3);
  const Vec3 up = rotate(body.state().orientation, {0.0, 1.0, 0.0});
  EXPECT_GT(up[1], std::cos(0.3));  // upright
}

TEST(Buoyancy, FollowsTheSimulatedSurfaceAtItsCentre) {
  // A swell of Tp = 10 s from the simulator (one cascade): the box's heave correlates with the
  // height query at its centre, and its standard deviation is the surface's within the response
  // of B.7 over the swell's band (|H| from 1.00 to 1.05).
  ocean::SimulationConfig c;
  c.sea.wind_sea.spectrum = {.model = ocean::SpectrumModel::jonswap,
                             .significant_wave_height_m = 1.0,
                             .peak_period_s = 10.0};
  c.sea.wind_sea.spreading = {.model = ocean::SpreadingModel::cos2s, .s = 20.0};
  c.resolution = 32;
  c.cascade_patch_sizes_m = {600.0};
  c.choppiness = 0.0;
  auto sim = ocean::make_simulator(c).value();
  auto body = FloatingBody::make(box(), {.position_m = {10.0, 0.0, 20.0}}).value();
  const SurfaceQuery surface = surface_of(*sim);
  std::vector<double> heave, eta;
  const double dt = 1.0 / 30;
  for (int i = 0; i < 90 * 30; ++i) {
    sim->step(i * dt);
    ASSERT_TRUE(body.step(surface, dt).ok());
    if (i * dt < 15.0) continue;
    std::array<ocean::HeightSample, 1> h{};
    const std::array<double, 2> centre{body.state().position_m[0], body.state().position_m[2]};
    sim->heights_at(std::span(&centre, 1), h);
    heave.push_back(body.state().position_m[1]);
    eta.push_back(h[0].height_m);
  }
  const auto mean = [](const std::vector<double>& v) {
    double s = 0;
    for (double x : v) s += x;
    return s / static_cast<double>(v.size());
  };
  const double mh = mean(heave), me = mean(eta);
  double shh = 0, see = 0, she = 0;
  for (std::size_t i = 0; i < heave.size(); ++i) {
    shh += (heave[i] - mh) * (heave[i] - mh);
    see += (eta[i] - me) * (eta[i] - me);
    she += (heave[i] - mh) * (eta[i] - me);
  }
  EXPECT_GT(she / std::sqrt(shh * see), 0.98);
  EXPECT_NEAR(std::sqrt(shh / see), 1.02, 0.04) << she / std::sqrt(shh * see);
}

}  // namespace
