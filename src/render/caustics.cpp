// Light under a wavy surface on the CPU (ocean/underwater.hpp; docs/rendering.md R.65, R.66): the
// caustics the surface's normals focus on a plane below it and the sunlight scattered once
// towards an eye in the water, which shaders/underwater.glsl restates. No device code.
//
// This work is based on:
// - Snell's law in vector form (the GLSL `refract`), n = 1.333 from air into sea water.
// - The irradiance a refracting surface gives a plane below it is the density of its refracted
//   rays: E/E₀ = 1/|det ∂X/∂x| of the ray mapping x ↦ X (M. Born and E. Wolf, "Principles of
//   Optics", 7th ed., 1999, §3.1.2, the intensity law of geometrical optics along a pencil of
//   rays); estimated as the area ratio of the refracted lattice (the flux of each surface
//   triangle over the area it lands on), which tiles the plane exactly under a flat surface, so
//   a flat surface gives exactly E₀ and a periodic one E₀ on average.
// - M. Ernst, T. Akenine-Möller and H. W. Jensen, "Interactive rendering of caustics using
//   interpolated warped volumes", Graphics Interface 2005: caustics from a water surface's
//   refracted beams, their irradiance the ratio of a beam's area at the surface to its area below.
// - L. G. Henyey and J. L. Greenstein, "Diffuse radiation in the galaxy", Astrophysical Journal
//   93, 1941: the phase function, its g the mean cosine of scattering; C. D. Mobley, "Light and
//   Water", 1994: the mean cosine 0.924 of Petzold's (1972) measured particle phase function.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "ocean/underwater.hpp"

namespace ocean::render {

namespace {

using Vec3 = std::array<double, 3>;

double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

// GLSL's refract(I, N, eta): the transmitted direction for unit I and N, eta = n₁/n₂.
Vec3 refract(const Vec3& i, const Vec3& n, double eta) {
  const double ni = dot(n, i), k = 1.0 - eta * eta * (1.0 - ni * ni);
  if (k < 0.0) return {0.0, 0.0, 0.0};
  const double f = eta * ni + std::sqrt(k);
  return {eta * i[0] - f * n[0], eta * i[1] - f * n[1], eta * i[2] - f * n[2]};
}

Vec3 normal_of(const std::array<double, 2>& s) {
  const double inv = 1.0 / std::sqrt(s[0] * s[0] + 1.0 + s[1] * s[1]);
  return {s[0] * inv, inv, s[1] * inv};
}

// The horizontal offset from the surface point to where the refracted sun ray through the
// normal N meets the plane `depth_m` below the mean level (R.65, the surface taken at y = 0).
std::array<double, 2> ray_offset(const Vec3& sun_dir, const Vec3& n, double depth_m) {
  const Vec3 t = refract({-sun_dir[0], -sun_dir[1], -sun_dir[2]}, n, 1.0 / kWaterIor);
  const double down = std::max(-t[1], 1e-6);
  return {depth_m * t[0] / down, depth_m * t[2] / down};
}

struct Photon {
  double x, z, w;  // where the ray lands, m; the flux weight of its surface point
};

// The irradiance a triangle of three photons gives X, over a flat surface's: the flux of the
// surface triangle (its area times the vertices' mean weight) over the area it lands on, where X
// lies inside it (folded triangles count with their area's magnitude), else 0; `inside` set
// where X lies inside.
double triangle_irradiance(const Photon& a, const Photon& b, const Photon& c, double x, double z,
                           bool& inside) {
  const auto cross = [](double ux, double uz, double vx, double vz) { return ux * vz - uz * vx; };
  double area2 = cross(b.x - a.x, b.z - a.z, c.x - a.x, c.z - a.z);
  double e0 = cross(b.x - a.x, b.z - a.z, x - a.x, z - a.z);
  double e1 = cross(c.x - b.x, c.z - b.z, x - b.x, z - b.z);
  double e2 = cross(a.x - c.x, a.z - c.z, x - c.x, z - c.z);
  if (area2 < 0.0) {
    area2 = -area2;
    e0 = -e0;
    e1 = -e1;
    e2 = -e2;
  }
  if (!(area2 > 0.0) || e0 < 0.0 || e1 < 0.0 || e2 < 0.0) return 0.0;
  inside = true;
  return (a.w + b.w + c.w) / 3.0 / area2;  // × the surface triangle's doubled area, by the caller
}

}  // namespace

double caustic_spacing_m(double depth_m, int half_width) {
  return std::max(kCausticMinSpacing_m,
                  std::max(depth_m, 0.0) * kCausticTilt / (static_cast<double>(half_width) - 1.5));
}

double caustic_irradiance(const SlopeField& slope, const std::array<double, 3>& sun_dir, double x_m,
                          double z_m, double depth_m, double spacing_m, int half_width) {
  if (sun_dir[1] <= 0.0) return 1.0;  // no sun: nothing to focus
  const double delta = spacing_m;
  const std::array<double, 2> o0 = ray_offset(sun_dir, {0.0, 1.0, 0.0}, depth_m);
  // The lattice point nearest to where the flat surface's ray to (x, z) starts, and the block
  // around it that holds every ray deflected by up to (half_width − 1.5)·δ.
  const double k0x = std::round((x_m - o0[0]) / delta), k0z = std::round((z_m - o0[1]) / delta);
  const int side = 2 * half_width + 1;
  std::vector<Photon> photons(static_cast<std::size_t>(side) * static_cast<std::size_t>(side));
  for (int j = 0; j < side; ++j)
    for (int i = 0; i < side; ++i) {
      const double xi = (k0x + i - half_width) * delta, zj = (k0z + j - half_width) * delta;
      const Vec3 n = normal_of(slope(xi, zj));
      // The flux the point's cell receives over a flat cell's: the projected area n·L/n_y
      // over L_y.
      const double w = std::max(dot(n, sun_dir), 0.0) / (n[1] * sun_dir[1]);
      const std::array<double, 2> o = ray_offset(sun_dir, n, depth_m);
      photons[static_cast<std::size_t>(j * side + i)] = {xi + o[0], zj + o[1], w};
    }
  // Each lattice cell as two triangles, (a, b, d) and (a, d, c); each surface triangle's doubled
  // area is δ².
  double sum = 0.0;
  bool covered = false;
  for (int j = 0; j + 1 < side; ++j)
    for (int i = 0; i + 1 < side; ++i) {
      const Photon& a = photons[static_cast<std::size_t>(j * side + i)];
      const Photon& b = photons[static_cast<std::size_t>(j * side + i + 1)];
      const Photon& c = photons[static_cast<std::size_t>((j + 1) * side + i)];
      const Photon& d = photons[static_cast<std::size_t>((j + 1) * side + i + 1)];
      sum += triangle_irradiance(a, b, d, x_m, z_m, covered) +
             triangle_irradiance(a, d, c, x_m, z_m, covered);
    }
  // A point no landed triangle of the block covers lies where rays deflected beyond the block
  // land: it takes the mean, 1, rather than a hole.
  return covered ? std::min(sum * delta * delta, kCausticMaxIrradiance) : 1.0;
}

std::array<double, 3> refracted_sun(const std::array<double, 3>& sun_dir) {
  return refract({-sun_dir[0], -sun_dir[1], -sun_dir[2]}, {0.0, 1.0, 0.0}, 1.0 / kWaterIor);
}

double henyey_greenstein_phase(double cos_theta, double g) {
  const double d = 1.0 + g * g - 2.0 * g * cos_theta;
  return (1.0 - g * g) / (4.0 * std::numbers::pi * d * std::sqrt(d));
}

double sun_single_scattering(const std::array<double, 3>& sun_dir,
                             const std::array<double, 3>& view, double depth_m, double r_m,
                             double absorption_per_m, double scattering_per_m) {
  const Vec3 t = refracted_sun(sun_dir);
  const double mu_w = -t[1], a = absorption_per_m, b = scattering_per_m;
  const double p = henyey_greenstein_phase(-dot(t, view), kWaterPhaseG);
  const double kappa = a + b - a * view[1] / mu_w;
  const double length = std::abs(kappa * r_m) < 1e-9 ? r_m
                        : std::isinf(r_m)            ? 1.0 / kappa
                                                     : -std::expm1(-kappa * r_m) / kappa;
  return b * p / mu_w * std::exp(-a * depth_m / mu_w) * length;
}

}  // namespace ocean::render
