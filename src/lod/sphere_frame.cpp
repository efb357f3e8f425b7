// The sea on a sphere (docs/rendering.md R.30–R.35): Paleologue's tangent frame and the polar
// caps' axis frame, the variance-preserving tri-planar weights, and the displaced point and its
// Jacobian in double precision.
//
// This work is based on:
//   - Paleologue, "Ocean Simulation with FFT and WebGPU" (2024), "Wrapping on a Sphere": the
//     tri-planar sampling, the displacement along the normal and the tangents t₁, t₂ (R.30);
//     the post calls θ the longitude and φ the latitude, but its t₁, t₂ are ∂n/∂φ/|…| and ∂n/∂θ
//     of n = (sin θ cos φ, cos θ, sin θ sin φ): θ is the colatitude, φ the longitude.
//   - Heitz & Neyret, "High-Performance By-Example Noise using a Histogram-Preserving Blending
//     Operator" (2018): weights whose squares sum to one keep the variance of a blend of
//     uncorrelated fields (R.32).
#include <cassert>
#include <cmath>

#include "ocean/sphere.hpp"

namespace ocean::sphere {

namespace {

Vec3 add(Vec3 a, Vec3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
Vec3 scale(Vec3 a, double s) { return {a.x * s, a.y * s, a.z * s}; }
double dot(Vec3 a, Vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
Vec3 cross(Vec3 a, Vec3 b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
Vec3 normalise(Vec3 a) { return scale(a, 1.0 / std::sqrt(dot(a, a))); }

// The plane axes (e1, e2) of the projection along axis a: (e1, axis, e2) right-handed like the
// flat sea's (x, y, z), so the projection along y is the flat sea itself (R.33).
constexpr Vec3 kPlaneAxes[3][2] = {{{0, 0, 1}, {0, 1, 0}},   // along x: (z, y)
                                   {{1, 0, 0}, {0, 0, 1}},   // along y: (x, z)
                                   {{0, 1, 0}, {1, 0, 0}}};  // along z: (y, x)

// The displacement vector d (tangent at n) and the height h of R.33–R.34.
void displacement(double radius_m, Vec3 n, const FlatSampler& sample, double& h, Vec3& d) {
  const std::array<double, 3> w = triplanar_weights(n);
  const Vec3 p = scale(n, radius_m);
  h = 0.0;
  d = {};
  for (std::size_t a = 0; a < 3; ++a) {
    if (w[a] <= 0.0) continue;
    const Vec3 e1 = kPlaneAxes[a][0], e2 = kPlaneAxes[a][1];
    const std::array<double, 3> s = sample(dot(p, e1), dot(p, e2));
    h += w[a] * s[1];
    const Vec3 da = add(scale(e1, s[0]), scale(e2, s[2]));
    d = add(d, scale(add(da, scale(n, -dot(da, n))), w[a]));  // on the tangent plane
  }
}

}  // namespace

TangentFrame seed_frame(Vec3 n) {
  const double sin_theta = std::hypot(n.x, n.z), cos_theta = n.y;
  assert(sin_theta > 0.0);
  const double cos_phi = n.x / sin_theta, sin_phi = n.z / sin_theta;
  return {.t1 = {-sin_phi, 0.0, cos_phi},
          .t2 = {cos_theta * cos_phi, -sin_theta, cos_theta * sin_phi},
          .n = n,
          .polar = false};
}

TangentFrame polar_frame(Vec3 n) {
  const Vec3 t1 = normalise(add(Vec3{0.0, 0.0, 1.0}, scale(n, -n.z)));
  return {.t1 = t1, .t2 = cross(n, t1), .n = n, .polar = true};
}

TangentFrame tangent_frame(Vec3 n) {
  return std::hypot(n.x, n.z) < kPolarCapSin ? polar_frame(n) : seed_frame(n);
}

std::array<double, 3> triplanar_weights(Vec3 n) {
  // Only axes within 60° of n take part (|n_a| > 1/2), and only one near a face's centre, so
  // the polar cap (sin θ < 0.1) reads the projection along y alone (R.32).
  std::array<double, 3> w{};
  const double c[3] = {std::abs(n.x), std::abs(n.y), std::abs(n.z)};
  double sum_sq = 0.0;
  for (std::size_t a = 0; a < 3; ++a) {
    const double t = std::max(c[a] - 0.5, 0.0);
    w[a] = t * t;
    sum_sq += w[a] * w[a];
  }
  const double inv = 1.0 / std::sqrt(sum_sq);  // > 0: the largest |n_a| ≥ 1/√3 > 1/2
  for (double& x : w) x *= inv;
  return w;
}

SurfacePoint displaced_point(double radius_m, Vec3 n, const FlatSampler& sample) {
  double h = 0.0;
  Vec3 d;
  displacement(radius_m, n, sample, h, d);
  const TangentFrame f = tangent_frame(n);
  return {.position_m = add(scale(n, radius_m + h), d),
          .height_m = h,
          .d1_m = dot(d, f.t1),
          .d2_m = dot(d, f.t2)};
}

double jacobian(double radius_m, Vec3 n, const TangentFrame& frame, const FlatSampler& sample,
                double step_m) {
  // Points at arc length ±step along t_j: n cos(s/R) + t_j sin(s/R).
  const double c = std::cos(step_m / radius_m), s = std::sin(step_m / radius_m);
  const Vec3 t[2] = {frame.t1, frame.t2};
  double a[2][2];
  for (int j = 0; j < 2; ++j) {
    double h = 0.0;
    Vec3 plus, minus;
    displacement(radius_m, add(scale(n, c), scale(t[j], s)), sample, h, plus);
    displacement(radius_m, add(scale(n, c), scale(t[j], -s)), sample, h, minus);
    const Vec3 derivative = scale(add(plus, scale(minus, -1.0)), 0.5 / step_m);
    for (int i = 0; i < 2; ++i) a[i][j] = (i == j ? 1.0 : 0.0) + dot(t[i], derivative);
  }
  return a[0][0] * a[1][1] - a[0][1] * a[1][0];
}

}  // namespace ocean::sphere
