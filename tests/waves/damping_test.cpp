// The damping of the sea's bands (ocean/waves.hpp, docs/waves.md W.12–W.14): a mask of 0 leaves
// only the low band's variance in the queried heights, a constant depth scales each band's
// variance by the Kitaigorodskii factor Φ computed here from its published closed form, and the
// maps are placed, sampled and validated as documented.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>

#include "ocean/backends.hpp"
#include "ocean/sim.hpp"
#include "ocean/waves.hpp"
#include "support/depth_law.hpp"

namespace {

using ocean::waves::Damping;
using ocean::waves::DampingParams;
using ocean::waves::HeightMap;
using ocean::waves::PlacedMap;
constexpr double kPi = std::numbers::pi;
constexpr double kG = 9.81;

// Two bands: [0, 0.335) on a 300 m patch and [0.335, ∞) on a 40 m patch, N = 64; a young wind
// sea (U10 = 6 m/s, 10 km fetch, λp ≈ 9 m) whose variance lies mostly in the short band.
ocean::SimulationConfig two_bands(std::uint64_t seed, double choppiness) {
  ocean::SimulationConfig c;
  c.sea.wind_sea.spectrum = {
      .model = ocean::SpectrumModel::jonswap, .wind_speed_mps = 6.0, .fetch_m = 1e4};
  c.resolution = 64;
  c.cascade_patch_sizes_m = {300.0, 40.0};
  c.choppiness = choppiness;
  c.seed = seed;
  return c;
}

std::unique_ptr<ocean::Simulator> sea(const ocean::SimulationConfig& c) {
  auto sim = ocean::make_simulator(c);
  EXPECT_TRUE(sim.ok()) << sim.status().message();
  sim.value()->step(4.0);
  return std::move(sim).value();
}

PlacedMap constant_map(double value, std::array<double, 2> origin, double size) {
  auto m = std::make_shared<HeightMap>();
  m->rows = m->cols = 4;
  m->values.assign(16, static_cast<float>(value));
  return {.map = m, .origin_m = origin, .size_m = size};
}

std::shared_ptr<const Damping> damping(const ocean::SimulationConfig& c,
                                       std::optional<PlacedMap> mask,
                                       std::optional<PlacedMap> bathymetry) {
  auto d = Damping::make({.mask = std::move(mask),
                          .bathymetry = std::move(bathymetry),
                          .band_wavenumbers_radpm = ocean::band_wavenumbers(c)});
  EXPECT_TRUE(d.ok()) << d.status().message();
  return std::make_shared<const Damping>(std::move(d).value());
}

std::vector<double> query(const ocean::Simulator& sim,
                          const std::vector<std::array<double, 2>>& at) {
  std::vector<ocean::HeightSample> out(at.size());
  sim.heights_at(at, out);
  std::vector<double> h;
  for (const auto& s : out) h.push_back(s.height_m);
  return h;
}

double mean_square(const std::vector<double>& h) {
  double s = 0.0;
  for (double v : h) s += v * v;
  return s / static_cast<double>(h.size());
}

// Mean square of cascade c's height texels: the band's own variance over its whole patch.
double texel_variance(const ocean::Simulator& sim, std::size_t c) {
  const auto& d = sim.frame().cascades[c].displacement;
  double s = 0.0;
  for (std::size_t i = 1; i < d.size(); i += 3) s += double(d[i]) * d[i];
  return s / static_cast<double>(d.size() / 3);
}

// n × n points spaced side/n from (x0, z0): one period of a patch of that side, sampled evenly.
std::vector<std::array<double, 2>> grid(double x0, double z0, double side, int n) {
  std::vector<std::array<double, 2>> p;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) p.push_back({x0 + side * i / n, z0 + side * j / n});
  return p;
}

using ocean_test::kitaigorodskii_phi;  // W.12's closed form (support/depth_law.hpp)

TEST(Damping, BandWavenumbersAreTheGeometricMeansOfTheBandEdges) {
  const double edge = 0.5 * kPi * 64 / 300.0;  // (M.7.1)
  const auto k = ocean::band_wavenumbers(two_bands(1, 0.0));
  ASSERT_EQ(k.size(), 2u);
  EXPECT_NEAR(k[0], std::sqrt(2 * kPi / 300.0 * edge), 1e-12);
  EXPECT_NEAR(k[1], std::sqrt(edge * kPi * 64 / 40.0), 1e-12);
}

TEST(Damping, MaskOfZeroLeavesTheLowBandsVariance) {
  // Left half of a 1000 m square masked (0), right half open (1); the step lies within one cell
  // (7.8 m) of x = 0, so the points keep 20 m away from it. Each side is queried at the texel
  // centres of one whole period of the low band's 300 m patch (choppiness 0, so a query reads the
  // point itself): there the low band's heights are its texels, and their mean square is the
  // band's variance over the patch.
  auto m = std::make_shared<HeightMap>();
  m->rows = m->cols = 128;
  for (int r = 0; r < 128; ++r)
    for (int c = 0; c < 128; ++c) m->values.push_back(c < 64 ? 0.0f : 1.0f);
  const PlacedMap mask{.map = m, .origin_m = {-500.0, -500.0}, .size_m = 1000.0};
  double masked = 0, open = 0, low = 0, all = 0;
  for (std::uint64_t seed = 1; seed <= 4; ++seed) {
    const auto c = two_bands(seed, 0.0);
    auto sim = sea(c);
    sim->set_damping(damping(c, mask, std::nullopt));
    masked += mean_square(query(*sim, grid(-337.5, -150.0, 300.0, 64)));  // x0 = −72·300/64
    open += mean_square(query(*sim, grid(18.75, -150.0, 300.0, 64)));     // x0 = 4·300/64
    low += texel_variance(*sim, 0);
    all += texel_variance(*sim, 0) + texel_variance(*sim, 1);
  }
  EXPECT_GT(all, 3.0 * low);      // the short band carries most of the sea: the mask must show
  EXPECT_GT(open, 3.0 * masked);  // and does, beside the masked half
  // The masked heights are the low band's texels exactly; float sums: 0.1 %.
  EXPECT_NEAR(masked / low, 1.0, 1e-3) << "masked " << masked << " low band " << low;
}

TEST(Damping, ConstantDepthScalesEachBandsVarianceByTheDepthFactor) {
  // Without choppiness a query returns the displacement at the point itself, so each band's
  // heights are separable: band 0 = heights with a mask of 0, band 1 = the rest.
  const auto points = grid(-140.0, -140.0, 280.0, 120);
  const PlacedMap zero = constant_map(0.0, {-500.0, -500.0}, 1000.0);
  for (const double depth : {1.0, 3.0, 8.0, 30.0}) {
    const PlacedMap floor = constant_map(depth, {-500.0, -500.0}, 1000.0);
    std::array<double, 2> band_deep{0, 0}, band_shallow{0, 0};
    for (std::uint64_t seed = 1; seed <= 3; ++seed) {
      const auto c = two_bands(seed, 0.0);
      auto sim = sea(c);
      sim->set_damping(damping(c, zero, std::nullopt));
      const auto low = query(*sim, points);
      sim->set_damping(nullptr);
      const auto both = query(*sim, points);
      sim->set_damping(damping(c, zero, floor));
      const auto low_d = query(*sim, points);
      sim->set_damping(damping(c, std::nullopt, floor));
      const auto both_d = query(*sim, points);
      std::vector<double> high(points.size()), high_d(points.size());
      for (std::size_t i = 0; i < points.size(); ++i) {
        high[i] = both[i] - low[i];
        high_d[i] = both_d[i] - low_d[i];
      }
      band_deep[0] += mean_square(low);
      band_deep[1] += mean_square(high);
      band_shallow[0] += mean_square(low_d);
      band_shallow[1] += mean_square(high_d);
    }
    const double edge = 0.5 * kPi * 64 / 300.0;
    const double k[2] = {std::sqrt(2 * kPi / 300.0 * edge), std::sqrt(edge * kPi * 64 / 40.0)};
    for (int b = 0; b < 2; ++b) {
      const double expected = kitaigorodskii_phi(std::sqrt(kG * k[b]), depth);
      EXPECT_NEAR(band_shallow[b] / band_deep[b], expected, 0.02 * expected)
          << "band " << b << " depth " << depth;
    }
  }
}

TEST(Damping, DepthWeightLimits) {
  const double k = 0.5;
  EXPECT_EQ(ocean::waves::depth_band_weight(k, std::numeric_limits<double>::infinity(), kG), 1.0);
  EXPECT_EQ(ocean::waves::depth_band_weight(k, 0.0, kG), 0.0);
  EXPECT_NEAR(ocean::waves::depth_band_weight(k, 100.0, kG), 1.0, 1e-12);  // kd = 50
  // Shallow water: Φ → ωh²/2 = k·d/2 (Kitaigorodskii et al. 1975; docs/math.md M.3.9).
  const double d = 1e-4;
  EXPECT_NEAR(std::pow(ocean::waves::depth_band_weight(k, d, kG), 2), k * d / 2, 1e-3 * k * d);
}

TEST(Damping, MapsArePlacedByTheirCornerAndNeutralOutside) {
  auto m = std::make_shared<HeightMap>();
  m->rows = 2;
  m->cols = 4;  // 4 m wide, 2 m deep at 1 m per sample
  m->values = {0, 1, 2, 3, 10, 11, 12, 13};
  const PlacedMap p{.map = m, .origin_m = {10.0, -5.0}, .size_m = 4.0};
  EXPECT_DOUBLE_EQ(ocean::waves::sample(p, 10.5, -4.5, -1.0), 0.0);   // sample (0, 0)
  EXPECT_DOUBLE_EQ(ocean::waves::sample(p, 13.5, -3.5, -1.0), 13.0);  // sample (1, 3)
  EXPECT_DOUBLE_EQ(ocean::waves::sample(p, 11.0, -4.0, -1.0), 5.5);   // between four samples
  EXPECT_DOUBLE_EQ(ocean::waves::sample(p, 10.1, -4.9, -1.0), 0.0);   // clamped at the edge
  EXPECT_DOUBLE_EQ(ocean::waves::sample(p, 9.9, -4.5, -1.0), -1.0);   // outside
  EXPECT_DOUBLE_EQ(ocean::waves::sample(p, 12.0, -2.9, -1.0), -1.0);  // past the last row
  // Outside both maps every band has weight 1; over a mask of 0 the low band keeps its 1.
  DampingParams d{.mask = constant_map(0.0, {0.0, 0.0}, 10.0),
                  .bathymetry = constant_map(5.0, {0.0, 0.0}, 10.0),
                  .band_wavenumbers_radpm = {0.05, 2.0}};
  const auto made = Damping::make(d);
  ASSERT_TRUE(made.ok()) << made.status().message();
  std::array<double, 2> w{};
  made.value().band_weights(-1.0, 5.0, w);
  EXPECT_EQ(w, (std::array<double, 2>{1.0, 1.0}));
  made.value().band_weights(5.0, 5.0, w);
  EXPECT_NEAR(w[0], std::sqrt(kitaigorodskii_phi(std::sqrt(kG * 0.05), 5.0)), 1e-9);
  EXPECT_EQ(w[1], 0.0);
}

TEST(Damping, LandCarriesNoWavesAndNothingBreaksOnIt) {
  // A negative depth is land, 3 m above the sea (W.28): every band's weight is 0 there, as on
  // the shoreline (d = 0), and no wave breaks.
  const auto made = Damping::make({.bathymetry = constant_map(-3.0, {0.0, 0.0}, 10.0),
                                   .band_wavenumbers_radpm = {0.05, 2.0},
                                   .band_variances_m2 = {1.0, 0.1}});
  ASSERT_TRUE(made.ok()) << made.status().message();
  std::array<double, 2> w{1.0, 1.0};
  made.value().band_weights(5.0, 5.0, w);
  EXPECT_EQ(w, (std::array<double, 2>{0.0, 0.0}));
  const ocean::waves::Surf s = made.value().surf(5.0, 5.0);
  EXPECT_EQ(s.depth_m, -3.0);
  EXPECT_EQ(s.rms_height_m, 0.0);
  EXPECT_EQ(s.max_height_m, 0.0);
  EXPECT_EQ(s.breaking_fraction, 0.0);
}

TEST(Damping, BadMapsAreRefusedNamingTheValue) {
  const auto fails = [](DampingParams p, const std::string& expected) {
    p.band_wavenumbers_radpm = {0.1, 1.0};
    const auto made = Damping::make(std::move(p));
    ASSERT_FALSE(made.ok());
    EXPECT_EQ(made.status().code(), ocean::ErrorCode::invalid_argument);
    EXPECT_NE(made.status().message().find(expected), std::string::npos) << made.status().message();
  };
  fails({.bathymetry = constant_map(-2e4, {0, 0}, 10.0)}, "bathymetry value 0 = -20000");
  fails({.bathymetry = constant_map(std::nan(""), {0, 0}, 10.0)}, "bathymetry value 0");
  fails({.mask = constant_map(1.5, {0, 0}, 10.0)}, "damping mask value 0 = 1.5");
  fails({.mask = constant_map(1.0, {0, 0}, 0.0)}, "size_m");
  fails({.mask = constant_map(1.0, {std::nan(""), 0}, 1.0)}, "origin_m[0]");
  fails({.mask = PlacedMap{.size_m = 1.0}}, "no map");
  DampingParams none;
  EXPECT_FALSE(Damping::make(none).ok());  // no bands
}

}  // namespace
