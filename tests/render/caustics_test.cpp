// Light under a wavy surface on the CPU (no device; docs/rendering.md R.65, R.66): the caustic
// gather gives the sun's irradiance exactly under a flat surface, conserves it exactly over a
// period of a periodic surface (focused or not), and reproduces the intensity law of
// geometrical optics, E/E₀ = w/|det ∂X/∂x| of the refracted-ray mapping, against a Jacobian taken
// by finite differences of the exactly refracted rays; for small waves under a high sun it
// tends to the weak-focusing limit 1 − d·(1 − 1/n)·∇²h. The single-scattering closed form of the
// light shafts equals its defining integral, and the phase function is normalised with mean
// cosine g.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "ocean/underwater.hpp"

namespace {

using namespace ocean::render;
using Vec3 = std::array<double, 3>;
constexpr double kPi = std::numbers::pi;

Vec3 sun_at(double elevation_deg, double azimuth_deg) {
  const double e = elevation_deg * kPi / 180.0, a = azimuth_deg * kPi / 180.0;
  return {std::cos(e) * std::cos(a), std::sin(e), std::cos(e) * std::sin(a)};
}

// A surface of a few waves, periodic over `period` (every wave an integer number of times):
// h = Σ A_j cos(k_j·x + φ_j); the slope field s = −∇h.
struct Waves {
  struct Wave {
    double kx, kz, amplitude, phase;
  };
  std::vector<Wave> waves;
  double height(double x, double z) const {
    double h = 0.0;
    for (const Wave& w : waves) h += w.amplitude * std::cos(w.kx * x + w.kz * z + w.phase);
    return h;
  }
  std::array<double, 2> slope(double x, double z) const {
    std::array<double, 2> s{0.0, 0.0};
    for (const Wave& w : waves) {
      const double d = w.amplitude * std::sin(w.kx * x + w.kz * z + w.phase);
      s[0] += w.kx * d;  // −∂h/∂x
      s[1] += w.kz * d;
    }
    return s;
  }
  double laplacian(double x, double z) const {
    double l = 0.0;
    for (const Wave& w : waves)
      l -= (w.kx * w.kx + w.kz * w.kz) * w.amplitude * std::cos(w.kx * x + w.kz * z + w.phase);
    return l;
  }
  SlopeField field() const {
    return [this](double x, double z) { return slope(x, z); };
  }
};

Waves three_waves(double period, double scale) {
  const double k = 2.0 * kPi / period;
  return {{{3 * k, 1 * k, 0.010 * scale, 0.3},
           {-2 * k, 4 * k, 0.006 * scale, 1.7},
           {5 * k, -3 * k, 0.003 * scale, 4.1}}};
}

// The refracted-ray mapping X(x) = x + d·t_xz/(−t_y), t the sun's ray refracted at the normal
// (Snell's law in vector form), and the flux weight w = (N·L)/(N_y·L_y) of the surface point.
struct RayMap {
  const Waves& surface;
  Vec3 sun;
  double depth;
  std::array<double, 2> at(double x, double z) const {
    const auto s = surface.slope(x, z);
    const double inv = 1.0 / std::sqrt(s[0] * s[0] + 1.0 + s[1] * s[1]);
    const Vec3 n{s[0] * inv, inv, s[1] * inv}, i{-sun[0], -sun[1], -sun[2]};
    const double eta = 1.0 / kWaterIor, ni = n[0] * i[0] + n[1] * i[1] + n[2] * i[2];
    const double f = eta * ni + std::sqrt(1.0 - eta * eta * (1.0 - ni * ni));
    const Vec3 t{eta * i[0] - f * n[0], eta * i[1] - f * n[1], eta * i[2] - f * n[2]};
    return {x + depth * t[0] / -t[1], z + depth * t[2] / -t[1]};
  }
  double weight(double x, double z) const {
    const auto s = surface.slope(x, z);
    return (sun[1] + s[0] * sun[0] + s[1] * sun[2]) / sun[1];
  }
  // det ∂X/∂x by central differences.
  double jacobian(double x, double z) const {
    constexpr double h = 1e-5;
    const auto xp = at(x + h, z), xm = at(x - h, z), zp = at(x, z + h), zm = at(x, z - h);
    const double a = (xp[0] - xm[0]) / (2 * h), b = (zp[0] - zm[0]) / (2 * h);
    const double c = (xp[1] - xm[1]) / (2 * h), d = (zp[1] - zm[1]) / (2 * h);
    return a * d - b * c;
  }
  // The surface point whose ray lands on (X, Z): Newton's method from the flat surface's.
  std::array<double, 2> preimage(double X, double Z) const {
    const auto flat = RayMap{Waves{}, sun, depth}.at(0.0, 0.0);
    double x = X - flat[0], z = Z - flat[1];
    for (int it = 0; it < 50; ++it) {
      constexpr double h = 1e-6;
      const auto f = at(x, z), fx = at(x + h, z), fz = at(x, z + h);
      const double r0 = f[0] - X, r1 = f[1] - Z;
      const double a = (fx[0] - f[0]) / h, b = (fz[0] - f[0]) / h;
      const double c = (fx[1] - f[1]) / h, d = (fz[1] - f[1]) / h;
      const double det = a * d - b * c;
      x -= (d * r0 - b * r1) / det;
      z -= (a * r1 - c * r0) / det;
    }
    return {x, z};
  }
};

TEST(Caustics, AFlatSurfaceGivesTheSunsIrradianceEverywhere) {
  const SlopeField flat = [](double, double) { return std::array<double, 2>{0.0, 0.0}; };
  double worst = 0.0;
  for (const double elevation : {90.0, 60.0, 25.0})
    for (const double depth : {0.5, 3.0, 17.0})
      for (const int half : {2, 3})
        for (int k = 0; k < 50; ++k) {
          const double x = -37.3 + 1.731 * k, z = 11.9 - 0.917 * k;
          const double c = caustic_irradiance(flat, sun_at(elevation, 40.0), x, z, depth,
                                              caustic_spacing_m(depth, half), half);
          worst = std::max(worst, std::abs(c - 1.0));
        }
  std::printf("flat surface: largest |E/E0 - 1| %.2e\n", worst);
  EXPECT_LT(worst, 1e-12);
}

// The mean over a period of the surface is the mean flux weight of the lattice's points, 1 for
// waves periodic on the lattice: every surface triangle's flux lands somewhere, whether or not
// the rays cross (beyond the focal depth), as long as the deflections stay in the gather's
// block and no point reaches the cap (kCausticMaxIrradiance, which beyond the focus clips the
// cusps' integrable peaks). The mean over the continuous plane is sampled here on a grid of X
// eight to a lattice step, so it holds to that sampling's error, not to rounding.
TEST(Caustics, TheMeanOverAPeriodIsTheSunsIrradiance) {
  constexpr double kPeriod = 8.0;
  constexpr int kSub = 8;  // X every δ/8
  const Waves surface = three_waves(kPeriod, 4.0);
  for (const double elevation : {90.0, 55.0})
    for (const double depth : {1.0, 4.0, 9.0}) {  // the last beyond the focus
      const Vec3 sun = sun_at(elevation, 25.0);
      // A lattice commensurate with the period, no finer than the renderer's at this depth (its
      // block holds the deflections).
      const int cells = std::min(64, static_cast<int>(kPeriod / caustic_spacing_m(depth, 3)));
      const double delta = kPeriod / cells;
      double sum = 0.0, lo = 1e9, hi = 0.0;
      const int n = cells * kSub;
      for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
          const double x = (i + 0.37) * kPeriod / n, z = (j + 0.61) * kPeriod / n;
          const double c = caustic_irradiance(surface.field(), sun, x, z, depth, delta);
          sum += c;
          lo = std::min(lo, c);
          hi = std::max(hi, c);
        }
      const double mean = sum / (static_cast<double>(n) * n);
      std::printf(
          "sun %.0f deg, depth %.0f m, lattice %.3f m: mean E/E0 %.12f (min %.3f, "
          "max %.3f)\n",
          elevation, depth, delta, mean, lo, hi);
      // The grid's error for a function constant on triangles a few grid steps wide; beyond the
      // focus also the energy of the cusps above the cap.
      EXPECT_NEAR(mean, 1.0, hi < kCausticMaxIrradiance ? 1e-3 : 1e-2);
      EXPECT_GT(hi - lo, 0.05);  // the waves do focus the light
    }
}

// Below the focal depth every bed point has one surface point; there the gather with a fine
// lattice approaches the intensity law w/|det J|, and for small slopes under a high sun the
// weak-focusing limit 1 − d·(1 − 1/n)·∇²h.
TEST(Caustics, ReproducesTheJacobianOfTheRefractedRays) {
  constexpr double kPeriod = 8.0;
  const Waves surface = three_waves(kPeriod, 4.0);
  double worst = 0.0, worst_weak = 0.0, largest_focus = 0.0;
  for (const double elevation : {90.0, 50.0})
    for (const double depth : {1.0, 2.5}) {
      const RayMap map{surface, sun_at(elevation, 25.0), depth};
      const double delta = 0.01;  // fine against the shortest wave (1.37 m)
      constexpr int kHalf = 40;   // a block that holds deflections up to 0.38 m
      for (int k = 0; k < 40; ++k) {
        const double X = 0.173 * k, Z = 0.311 * k - 3.0;
        const auto x = map.preimage(X, Z);
        const double jac = map.jacobian(x[0], x[1]);
        ASSERT_GT(jac, 0.0) << "rays cross: the test's depth is beyond the focus";
        const double expected = map.weight(x[0], x[1]) / jac;
        const double got = caustic_irradiance(surface.field(), map.sun, X, Z, depth, delta, kHalf);
        worst = std::max(worst, std::abs(got - expected) / expected);
        largest_focus = std::max(largest_focus, std::abs(expected - 1.0));
      }
    }
  // Small waves under a vertical sun: E/E₀ − 1 against −d·(1 − 1/n)·∇²h at the same point.
  const Waves small = three_waves(kPeriod, 0.2);
  double weak_scale = 0.0;
  for (int k = 0; k < 40; ++k) {
    const double depth = 3.0, X = 0.173 * k, Z = 0.311 * k - 3.0;
    const double got = caustic_irradiance(small.field(), {0.0, 1.0, 0.0}, X, Z, depth, 0.01, 6);
    const double weak = -depth * (1.0 - 1.0 / kWaterIor) * small.laplacian(X, Z);
    worst_weak = std::max(worst_weak, std::abs((got - 1.0) - weak));
    weak_scale = std::max(weak_scale, std::abs(weak));
  }
  std::printf(
      "Jacobian: largest relative error %.4f (|E/E0 - 1| up to %.3f); weak focusing: "
      "largest error %.2e of a modulation up to %.2e\n",
      worst, largest_focus, worst_weak, weak_scale);
  EXPECT_LT(worst, 0.01);
  EXPECT_GT(largest_focus, 0.2);  // the cases do focus
  EXPECT_LT(worst_weak, 0.05 * weak_scale);
}

TEST(Shafts, TheClosedFormIsTheSingleScatteringIntegral) {
  const Vec3 sun = sun_at(60.0, 30.0);
  const Vec3 t = refracted_sun(sun);
  EXPECT_NEAR(std::hypot(t[0], t[2]) / -t[1],
              std::tan(std::asin(std::cos(60.0 * kPi / 180.0) / kWaterIor)), 1e-12);  // Snell
  const double mu_w = -t[1];
  double worst = 0.0;
  for (const Vec3 view :
       {Vec3{1.0, 0.0, 0.0}, Vec3{0.6, -0.8, 0.0}, Vec3{-t[0], -t[1], -t[2]}, Vec3{0.0, 0.6, 0.8}})
    for (const double r : {2.0, 15.0, 80.0}) {
      const double depth = 6.0, a = 0.0565, b = 0.2;
      const double closed = sun_single_scattering(sun, view, depth, r, a, b);
      // ∫₀^r b·p(θ)·(1/μ_w)·e^{−a·z(s)/μ_w}·e^{−(a+b)·s} ds, z(s) = depth − s·v_y, midpoint rule.
      const double p = henyey_greenstein_phase(-(t[0] * view[0] + t[1] * view[1] + t[2] * view[2]),
                                               kWaterPhaseG);
      constexpr int kSteps = 200000;
      double sum = 0.0;
      for (int i = 0; i < kSteps; ++i) {
        const double s = (i + 0.5) * r / kSteps, z = depth - s * view[1];
        sum += b * p / mu_w * std::exp(-a * z / mu_w) * std::exp(-(a + b) * s) * r / kSteps;
      }
      worst = std::max(worst, std::abs(closed - sum) / sum);
    }
  std::printf("single scattering: closed form against the integral, largest relative error %.2e\n",
              worst);
  EXPECT_LT(worst, 1e-8);
}

TEST(Shafts, ThePhaseFunctionIsNormalisedWithMeanCosineG) {
  constexpr int kSteps = 400000;
  double norm = 0.0, mean_cos = 0.0;
  for (int i = 0; i < kSteps; ++i) {  // ∫ p dΩ = 2π ∫₋₁¹ p(μ) dμ
    const double mu = -1.0 + (i + 0.5) * 2.0 / kSteps;
    const double p = henyey_greenstein_phase(mu, kWaterPhaseG);
    norm += 2.0 * kPi * p * 2.0 / kSteps;
    mean_cos += 2.0 * kPi * mu * p * 2.0 / kSteps;
  }
  EXPECT_NEAR(norm, 1.0, 1e-4);
  EXPECT_NEAR(mean_cos, kWaterPhaseG, 1e-4);
}

}  // namespace
