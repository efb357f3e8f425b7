// Whitecaps (docs/math.md M.7.4): the foam of FoamSource::breaking against the published laws.
//
// The source is Longuet-Higgins (1969)'s breaking criterion, a downward acceleration beyond α·g
// with α = ½ (the crest of Stokes's limiting wave), which for linear waves is J < 1 − λ·α on the
// whole surface. Two checks, neither from our own output:
//   - each cascade's mean foam is the probability of that criterion on a Gaussian sea whose
//     slope variance is Cox & Munk (1954)'s clean-surface law (the whole slope spectrum the
//     criterion sees, which the statistics tests hold to Cox & Munk within 10–20 %);
//   - the whitecap fraction a renderer draws follows Monahan & O'Muircheartaigh (1980),
//     W = 3.84e-6·U10^3.41, from 5 to 20 m/s.
// A threshold on a Gaussian field grows like Φ(−α/σ(U)) with σ² linear in U (Cox & Munk), not
// like U^3.41: from 5 to 20 m/s it grows about 35-fold where Monahan's law grows 113-fold. The
// ratio to the law therefore peaks near 7.5 m/s (2.1) and falls to 0.56 at 20 m/s; the bound
// below (a factor 2.2) is what this physics reaches, slightly wider than Monahan's own factor 2.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <vector>

#include "ocean/backends.hpp"
#include "ocean/plan.hpp"
#include "ocean/statistics.hpp"

namespace whitecaps {  // named: the test target is a unity build

using ocean::SimulationConfig;

// The `moderate` preset's sea and cascades (presets/moderate.json) at wind speed U.
SimulationConfig moderate(double wind_speed_mps) {
  SimulationConfig c;
  c.sea.wind_sea.spectrum.wind_speed_mps = wind_speed_mps;
  c.cascade_patch_sizes_m = {1000.0, 233.0, 57.0, 13.0};
  return c;
}

ocean::TaskRunner& runner() {
  static const std::unique_ptr<ocean::TaskRunner> r = ocean::make_tbb_runner();
  return *r;
}

// Φ(x), independently of the library's approximation.
double normal_cdf(double x) { return 0.5 * std::erfc(-x / std::sqrt(2.0)); }

struct Coverage {
  std::vector<double> cascade_mean;  // each cascade's mean foam over the frames
  double drawn = 0.0;                // Σ weight·mean, the renderer's composition (R.11)
};

// The mean foam of frames 2 s to 6 s after the start, 0.1 s apart (sampled every 0.4 s): foam
// accumulated over the frames before, as a renderer sees it.
Coverage coverage(const SimulationConfig& config) {
  auto made = ocean::make_simulator(
      config, "cpu",
      std::shared_ptr<ocean::TaskRunner>(std::shared_ptr<ocean::TaskRunner>(), &runner()));
  EXPECT_TRUE(made.ok()) << made.status().message();
  Coverage out;
  if (!made.ok()) return out;
  ocean::Simulator& sim = *made.value();
  const std::size_t cascades = config.cascade_patch_sizes_m.size();
  out.cascade_mean.assign(cascades, 0.0);
  int samples = 0;
  for (int frame = 0; frame <= 60; ++frame) {
    sim.step(0.1 * frame);
    if (frame < 20 || frame % 4 != 0) continue;
    ++samples;
    for (std::size_t c = 0; c < cascades; ++c) {
      double sum = 0.0;
      for (float f : sim.frame().cascades[c].foam) sum += f;
      out.cascade_mean[c] += sum / static_cast<double>(sim.frame().cascades[c].foam.size());
    }
  }
  const std::vector<double>& weights = sim.plan().foam().weights;
  EXPECT_EQ(weights.size(), cascades);
  double weight_sum = 0.0;
  for (std::size_t c = 0; c < cascades; ++c) {
    out.cascade_mean[c] /= samples;
    out.drawn += weights[c] * out.cascade_mean[c];
    weight_sum += weights[c];
  }
  EXPECT_NEAR(weight_sum, 1.0, 1e-12);
  return out;
}

TEST(Whitecaps, EachCascadeHoldsTheBreakingProbabilityOfACoxMunkSea) {
  for (double u10 : {5.0, 10.0, 20.0}) {
    const Coverage got = coverage(moderate(u10));
    // Cox & Munk's wind is at 12.5 m: U12.5 = U10·(1 + ln(1.25)/ln(10/z0)) ≈ 1.03·U10 over the
    // sea's roughness length (neutral log profile, z0 ≈ 2·10⁻⁴ m).
    const double sigma = std::sqrt(ocean::cox_munk_mean_square_slope(1.03 * u10));
    const double expected = normal_cdf(-0.5 / sigma);
    for (std::size_t c = 0; c < got.cascade_mean.size(); ++c) {
      EXPECT_NEAR(got.cascade_mean[c] / expected, 1.0, 0.2)
          << "U10 = " << u10 << " m/s, cascade " << c << ": " << got.cascade_mean[c]
          << " against Φ(−α/σ_CM) = " << expected;
    }
  }
}

TEST(Whitecaps, CoverageFollowsMonahansLawFrom5To20MetresPerSecond) {
  double previous = 0.0;
  for (double u10 : {5.0, 7.5, 10.0, 12.5, 15.0, 20.0}) {
    const double drawn = coverage(moderate(u10)).drawn;
    const double law = ocean::monahan_whitecap_coverage(u10);
    const double ratio = drawn / law;
    std::printf("U10 = %4.1f m/s: coverage %.4f %%, Monahan %.4f %%, ratio %.2f\n", u10,
                100.0 * drawn, 100.0 * law, ratio);
    EXPECT_GT(ratio, 1.0 / 2.2) << "U10 = " << u10 << " m/s";
    EXPECT_LT(ratio, 2.2) << "U10 = " << u10 << " m/s";
    EXPECT_GT(drawn, previous) << "coverage must grow with the wind";
    previous = drawn;
  }
}

TEST(Whitecaps, TheRampStillDependsOnTheCascadesAlone) {
  // FoamSource::ramp (each cascade's own J, Vincevičius 2024) is kept for configurations that
  // name it; it is far below the law (each band alone rarely reaches J < 0.8).
  SimulationConfig c = moderate(10.0);
  c.foam.source = ocean::FoamSource::ramp;
  auto plan = ocean::SimulationPlan::make(c);
  ASSERT_TRUE(plan.ok());
  EXPECT_TRUE(plan.value().foam().weights.empty());
  const auto stats = ocean::compute_surface_stats(c, 1, 3.0, runner());
  ASSERT_TRUE(stats.ok());
  EXPECT_LT(stats.value().whitecap_coverage, 0.25 * ocean::monahan_whitecap_coverage(10.0));
}

TEST(Whitecaps, NoHorizontalDisplacementNoBreakingSeen) {
  // λ = 0: J ≡ 1 carries no acceleration, so nothing may foam (not Φ(0) = ½).
  SimulationConfig c = moderate(15.0);
  c.choppiness = 0.0;
  const auto stats = ocean::compute_surface_stats(c, 1, 1.0, runner());
  ASSERT_TRUE(stats.ok());
  EXPECT_EQ(stats.value().whitecap_coverage, 0.0);
  EXPECT_EQ(stats.value().mean_foam, 0.0);
}

TEST(Whitecaps, StatsReportTheLawBeside) {
  const auto stats = ocean::compute_surface_stats(moderate(10.0), 1, 0.0, runner());
  ASSERT_TRUE(stats.ok());
  ASSERT_TRUE(stats.value().monahan_whitecap_coverage.has_value());
  EXPECT_NEAR(*stats.value().monahan_whitecap_coverage, 3.84e-6 * std::pow(10.0, 3.41), 1e-12);
  EXPECT_GT(stats.value().whitecap_coverage, 0.0);
}

}  // namespace whitecaps
