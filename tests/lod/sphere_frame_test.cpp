// The sea on a sphere (docs/rendering.md R.30–R.35, R.38): Paleologue's tangent frame is
// orthonormal and right-handed everywhere, the poles included; the polar caps' frame meets it on
// the meridian φ = 0; displaced points stay in the height band about R; the Jacobian does not see
// the frame switch; the tri-planar blend keeps the height variance across its blend zones; the
// shader's single-precision offsets hold a millimetre on Earth at any latitude and longitude.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "ocean/sphere.hpp"

namespace {

using namespace ocean::sphere;
constexpr double kPi = std::numbers::pi;

double dot(Vec3 a, Vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
Vec3 cross(Vec3 a, Vec3 b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
// n of colatitude θ and longitude φ (R.30).
Vec3 direction(double theta, double phi) {
  return {std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi)};
}

void expect_orthonormal(const TangentFrame& f, double tol) {
  EXPECT_NEAR(dot(f.t1, f.t1), 1.0, tol);
  EXPECT_NEAR(dot(f.t2, f.t2), 1.0, tol);
  EXPECT_NEAR(dot(f.t1, f.t2), 0.0, tol);
  EXPECT_NEAR(dot(f.t1, f.n), 0.0, tol);
  EXPECT_NEAR(dot(f.t2, f.n), 0.0, tol);
  const Vec3 c = cross(f.t1, f.n);  // t1 × n = −t2: (t1, n, −t2) is (east, up, north)
  EXPECT_NEAR(c.x, -f.t2.x, tol);
  EXPECT_NEAR(c.y, -f.t2.y, tol);
  EXPECT_NEAR(c.z, -f.t2.z, tol);
}

TEST(SphereFrame, SeedFrameIsPaleologuesFormula) {
  for (double theta : {0.3, 1.0, kPi / 2, 2.5})
    for (double phi : {-3.0, -1.0, 0.0, 0.7, 2.0}) {
      const TangentFrame f = seed_frame(direction(theta, phi));
      EXPECT_NEAR(f.t1.x, -std::sin(phi), 1e-15);
      EXPECT_EQ(f.t1.y, 0.0);
      EXPECT_NEAR(f.t1.z, std::cos(phi), 1e-15);
      EXPECT_NEAR(f.t2.x, std::cos(theta) * std::cos(phi), 1e-15);
      EXPECT_NEAR(f.t2.y, -std::sin(theta), 1e-15);
      EXPECT_NEAR(f.t2.z, std::cos(theta) * std::sin(phi), 1e-15);
    }
}

TEST(SphereFrame, OrthonormalEverywhereIncludingThePoles) {
  std::vector<double> thetas{0.0, 1e-12,   1e-6,         0.05,       0.0999, 0.1001,
                             1.0, kPi / 2, kPi - 0.1002, kPi - 1e-9, kPi};
  for (int i = 1; i < 64; ++i) thetas.push_back(kPi * i / 64.0);
  for (double theta : thetas)
    for (int j = 0; j < 32; ++j) {
      const TangentFrame f = tangent_frame(direction(theta, 2 * kPi * j / 32.0 - kPi));
      expect_orthonormal(f, 1e-12);
      EXPECT_EQ(f.polar, std::sin(theta) < kPolarCapSin - 1e-12) << theta;
    }
}

TEST(SphereFrame, PolarFrameMeetsTheSeedFrameOnTheZeroMeridian) {
  for (double theta : {0.05, 0.1, 1.0, kPi - 0.05}) {
    const Vec3 n = direction(theta, 0.0);
    const TangentFrame a = seed_frame(n), b = polar_frame(n);
    EXPECT_NEAR(dot(a.t1, b.t1), 1.0, 1e-14);
    EXPECT_NEAR(dot(a.t2, b.t2), 1.0, 1e-14);
  }
}

// A sea of random plane waves: heights of variance Σa²/2, choppy displacement along each
// wave's direction; |h| ≤ Σa and |D| ≤ Σa·λ.
struct Waves {
  std::vector<double> a, kx, kz, phase;
  double choppiness = 0.8;
  explicit Waves(int count, double shortest_m, double longest_m, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (int i = 0; i < count; ++i) {
      const double wavelength = shortest_m * std::pow(longest_m / shortest_m, u(rng));
      const double k = 2 * kPi / wavelength, dir = 2 * kPi * u(rng);
      a.push_back(0.1), kx.push_back(k * std::cos(dir)), kz.push_back(k * std::sin(dir));
      phase.push_back(2 * kPi * u(rng));
    }
  }
  std::array<double, 3> operator()(double x, double z) const {
    std::array<double, 3> d{};
    for (std::size_t i = 0; i < a.size(); ++i) {
      const double arg = kx[i] * x + kz[i] * z + phase[i], k = std::hypot(kx[i], kz[i]);
      d[1] += a[i] * std::cos(arg);
      d[0] -= choppiness * a[i] * kx[i] / k * std::sin(arg);
      d[2] -= choppiness * a[i] * kz[i] / k * std::sin(arg);
    }
    return d;
  }
  double max_height() const { return 0.1 * static_cast<double>(a.size()); }
  double variance() const { return 0.005 * static_cast<double>(a.size()); }
};

TEST(SphereSurface, DisplacedPointsStayInTheHeightBand) {
  const Waves waves(12, 8.0, 120.0, 1);
  for (double radius : {5000.0, 6.371e6}) {
    std::mt19937 rng(7);
    std::normal_distribution<double> g;
    // Σ w_a ≤ √3 when Σ w_a² = 1 (R.32); the tangential displacement adds |d|²/(2R) at most.
    const double h = waves.max_height(), d = waves.choppiness * h * std::sqrt(3.0);
    for (int i = 0; i < 4000; ++i) {
      Vec3 n{g(rng), g(rng), g(rng)};
      const double len = std::sqrt(dot(n, n));
      n = {n.x / len, n.y / len, n.z / len};
      const SurfacePoint p = displaced_point(radius, n, FlatSampler(waves));
      const double r = std::sqrt(dot(p.position_m, p.position_m));
      EXPECT_GE(r, radius - std::sqrt(3.0) * h);
      EXPECT_LE(r, radius + std::sqrt(3.0) * h + d * d / radius);
      EXPECT_NEAR(r, std::hypot(radius + p.height_m, std::hypot(p.d1_m, p.d2_m)), 1e-6 * radius);
    }
  }
}

TEST(SphereSurface, JacobianIgnoresWhereTheFrameSwitches) {
  const Waves waves(8, 10.0, 60.0, 3);
  const double radius = 5000.0;
  for (double phi : {0.4, 1.3, 2.9, -2.0}) {
    const Vec3 n = direction(std::asin(kPolarCapSin), phi);  // on the cap's edge
    const double js = jacobian(radius, n, seed_frame(n), FlatSampler(waves), 0.01);
    const double jp = jacobian(radius, n, polar_frame(n), FlatSampler(waves), 0.01);
    EXPECT_NEAR(js, jp, 1e-5) << phi;
    EXPECT_LT(dot(seed_frame(n).t1, polar_frame(n).t1), 0.999);  // the frames differ here
  }
  // At the pole the projection along y alone is read: J = 1 + ∂Dx/∂x for a wave along x.
  const FlatSampler along_x = [](double x, double) {
    return std::array<double, 3>{-0.5 * std::sin(0.5 * x), std::cos(0.5 * x), 0.0};
  };
  const Vec3 pole{0.0, 1.0, 0.0};
  EXPECT_NEAR(jacobian(radius, pole, tangent_frame(pole), along_x, 0.01), 1.0 - 0.25, 1e-4);
}

// Sample variance of the heights at n = normalise(base + t·spread) over a grid of t: points
// about 40 m apart, beyond the waves' correlation.
double height_variance(Vec3 base, Vec3 spread, const Waves& waves, double radius) {
  double sum = 0.0, sum_sq = 0.0;
  const int count = 3000;
  for (int i = 0; i < count; ++i) {
    const double t = -0.25 + 0.5 * i / (count - 1.0);
    Vec3 n{base.x + t * spread.x, base.y + t * spread.y, base.z + t * spread.z};
    const double len = std::sqrt(dot(n, n));
    n = {n.x / len, n.y / len, n.z / len};
    const double h = displaced_point(radius, n, FlatSampler(waves)).height_m;
    sum += h, sum_sq += h * h;
  }
  return sum_sq / count - (sum / count) * (sum / count);
}

TEST(SphereSurface, TriplanarBlendKeepsTheVarianceAcrossTheBlendZones) {
  // A seam shows as a band of other contrast: compare the heights' variance along the blend
  // zone between the x and y projections (n ∝ (1, 1, t)) and where y alone is read (n ∝
  // (t, 1, 0.2)), both against the waves' Σa²/2. 3000 samples: relative σ of a variance
  // √(2/3000) = 2.6 %; 4σ tolerance. A plain (Σw = 1) blend would halve it at the zone's centre.
  const Waves waves(40, 6.0, 30.0, 11);
  const double radius = 5.0e5;
  const double expected = waves.variance(), tol = 4.0 * std::sqrt(2.0 / 3000.0);
  const double blend = height_variance({1, 1, 0}, {0, 0, 1}, waves, radius);
  const double pure = height_variance({0, 1, 0.2}, {1, 0, 0}, waves, radius);
  const double corner = height_variance({1, 1, 1}, {1, -1, 0}, waves, radius);
  EXPECT_NEAR(blend / expected, 1.0, tol);
  EXPECT_NEAR(pure / expected, 1.0, tol);
  EXPECT_NEAR(corner / expected, 1.0, tol);
  const std::array<double, 3> w = triplanar_weights({std::sqrt(0.5), std::sqrt(0.5), 0.0});
  EXPECT_NEAR(w[0] * w[0] + w[1] * w[1] + w[2] * w[2], 1.0, 1e-15);
  EXPECT_NEAR(w[0], w[1], 1e-15);
}

TEST(SphereSurface, SinglePrecisionOffsetsHoldAMillimetreOnEarth) {
  // The vertex shader's dir(c + δ) − dir(c) (R.38) for 64 m patches at level 17 of every face,
  // at random places: R times its error stays under a millimetre, where the plain difference of
  // two normalised floats errs by decimetres.
  const double radius = 6.371e6, size = 2.0 / (1 << 17);
  std::mt19937 rng(5);
  std::uniform_int_distribution<int> cell(0, (1 << 17) - 1), vertex(0, 64);
  double worst = 0.0, naive_worst = 0.0;
  for (int i = 0; i < 3000; ++i) {
    const int face = i % kFaces;
    const double cu = -1.0 + (cell(rng) + 0.5) * size, cv = -1.0 + (cell(rng) + 0.5) * size;
    const double du = (vertex(rng) / 64.0 - 0.5) * size, dv = (vertex(rng) / 64.0 - 0.5) * size;
    const Vec3 c = cube_point(face, cu, cv), v = cube_point(face, cu + du, cv + dv);
    const Vec3 dc = cube_to_sphere(c), dvv = cube_to_sphere(v);
    const Vec3 exact{radius * (dvv.x - dc.x), radius * (dvv.y - dc.y), radius * (dvv.z - dc.z)};
    const std::array<float, 3> cf{static_cast<float>(c.x), static_cast<float>(c.y),
                                  static_cast<float>(c.z)};
    const std::array<float, 3> df{static_cast<float>(v.x - c.x), static_cast<float>(v.y - c.y),
                                  static_cast<float>(v.z - c.z)};
    ASSERT_EQ(static_cast<double>(cf[0]), c.x);  // dyadic: exact in float
    const std::array<float, 3> o = sphere_offset(cf, df);
    const std::array<float, 3> vf{cf[0] + df[0], cf[1] + df[1], cf[2] + df[2]};
    const float lc = std::sqrt(cf[0] * cf[0] + cf[1] * cf[1] + cf[2] * cf[2]);
    const float lv = std::sqrt(vf[0] * vf[0] + vf[1] * vf[1] + vf[2] * vf[2]);
    for (int k = 0; k < 3; ++k) {
      const double e = k == 0 ? exact.x : (k == 1 ? exact.y : exact.z);
      worst = std::max(worst, std::abs(radius * o[static_cast<std::size_t>(k)] - e));
      const float naive =
          vf[static_cast<std::size_t>(k)] / lv - cf[static_cast<std::size_t>(k)] / lc;
      naive_worst = std::max(naive_worst, std::abs(radius * naive - e));
    }
  }
  EXPECT_LT(worst, 1e-3);
  EXPECT_GT(naive_worst, 1e-2);  // what the stable form is for
}

}  // namespace
