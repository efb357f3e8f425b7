// The seabed through calm water (lavapipe, validation layer on): seen straight down, a checker on
// the bed appears where Snell's law puts it — every pixel's refracted ray lands on a square of
// the colour the pixel shows — and not where unrefracted rays would put it; its contrast fades
// between two depths per channel as R.23 states with the absorption of pure water
// (Pope & Fry 1997), the sun's path lengthened by its refraction.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "ocean/backends.hpp"
#include "render/render_helpers.hpp"
#include "support/require_devices.hpp"

namespace {

using namespace ocean::render;
namespace helpers = ocean::render::testing;
constexpr int kBedW = 120, kBedH = 80;
constexpr double kIor = 1.333, kHeight = 8.0;

using Rig = ocean::render::testing::ValidatedRig;

// Calm water: a 1 m/s breeze over 1 km, whose waves the 47 m cascade barely resolves (slopes
// below 1e-2 rad: a refraction offset under 1 cm at these depths).
std::unique_ptr<Rig> make_bed_rig() {
  auto rig = std::make_unique<Rig>();
  rig->ctx = helpers::graphics_context();
  if (rig->ctx == nullptr) return nullptr;
  ocean::SimulationConfig c = helpers::small_config();
  c.sea.wind_sea.spectrum.wind_speed_mps = 1.0;
  c.sea.wind_sea.spectrum.fetch_m = 1000.0;
  c.choppiness = 0.0;
  auto sim = ocean::make_simulator(c).value();
  sim->step(1.0);
  rig->renderer = Renderer::make(rig->ctx, {.width = kBedW, .height = kBedH}).value();
  EXPECT_TRUE(rig->renderer->configure(ocean::SimulationPlan::make(c).value().surface()).ok());
  EXPECT_TRUE(rig->renderer->upload(sim->frame()).ok());
  return rig;
}

View straight_down(double depth_m, double period_m) {
  View v = helpers::eye_level_view(kBedW, kBedH);
  v.camera.position_m = {0.0, kHeight, 0.0};
  v.camera.target_m = {1e-3, 0.0, 0.0};
  v.camera.fov_y_rad = 40.0 * std::numbers::pi / 180.0;
  // The sun's glint lies outside the picture; its faint tail varies along x alone (azimuth 0),
  // which the four squares around the centre average out exactly.
  v.shading.sun_elevation_deg = 45.0;
  v.shading.sun_azimuth_deg = 0.0;
  v.shading.ripples = false;  // the refraction of a plane: no capillary ripples (R.62) on it
  v.seabed = {.enabled = true,
              .depth_m = depth_m,
              .albedo = {0.6, 0.6, 0.6},
              .pattern = SeabedPattern::checker,
              .period_m = period_m};
  return v;
}

// Inverse of a column-major 4×4 matrix by Gauss–Jordan elimination with partial pivoting.
std::array<double, 16> inverse(const std::array<double, 16>& m) {
  double a[4][8];
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) {
      a[r][c] = m[static_cast<std::size_t>(c * 4 + r)];
      a[r][c + 4] = r == c ? 1.0 : 0.0;
    }
  for (int c = 0; c < 4; ++c) {
    int p = c;
    for (int r = c + 1; r < 4; ++r)
      if (std::abs(a[r][c]) > std::abs(a[p][c])) p = r;
    for (int k = 0; k < 8; ++k) std::swap(a[c][k], a[p][k]);
    const double d = a[c][c];
    for (int k = 0; k < 8; ++k) a[c][k] /= d;
    for (int r = 0; r < 4; ++r)
      if (r != c) {
        const double f = a[r][c];
        for (int k = 0; k < 8; ++k) a[r][k] -= f * a[c][k];
      }
  }
  std::array<double, 16> out{};
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) out[static_cast<std::size_t>(c * 4 + r)] = a[r][c + 4];
  return out;
}

// Where pixel (x, y)'s ray meets the bed: from the camera to the flat surface y = 0, then along
// the refracted direction (Snell) — or straight on when `refract` is false — down to y = −depth.
struct BedHit {
  double x, z, t;  // the bed point and the path length in the water
};
BedHit bed_point(const View& view, int px, int py, bool refract) {
  const std::array<double, 16> inv = inverse(ocean::lod::view_projection(view.camera).m);
  const double nx = (px + 0.5) / kBedW * 2.0 - 1.0, ny = 1.0 - (py + 0.5) / kBedH * 2.0;
  double p[2][3];
  for (int k = 0; k < 2; ++k) {
    const double in[4] = {nx, ny, static_cast<double>(k), 1.0};
    double out[4] = {0, 0, 0, 0};
    for (int r = 0; r < 4; ++r)
      for (int c = 0; c < 4; ++c) out[r] += inv[static_cast<std::size_t>(c * 4 + r)] * in[c];
    for (int r = 0; r < 3; ++r) p[k][r] = out[r] / out[3];
  }
  double d[3] = {p[1][0] - p[0][0], p[1][1] - p[0][1], p[1][2] - p[0][2]};
  const double len = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
  for (double& v : d) v /= len;
  const auto& eye = view.camera.position_m;
  const double s = -eye.y / d[1];  // to the surface
  const double x0 = eye.x + s * d[0], z0 = eye.z + s * d[2];
  double t[3] = {d[0], d[1], d[2]};
  if (refract) {  // GLSL refract(I, N = +y, η = 1/n)
    // refract(I, N) = η·I − (η·(N·I) + √k)·N, N·I = d_y, k = 1 − η²(1 − (N·I)²).
    const double eta = 1.0 / kIor, n_dot_i = d[1];
    const double k = 1.0 - eta * eta * (1.0 - n_dot_i * n_dot_i);
    for (int i = 0; i < 3; ++i) t[i] = eta * d[i];
    t[1] -= eta * n_dot_i + std::sqrt(k);
  }
  const double depth = view.seabed.depth_m, path = depth / -t[1];
  return {x0 + path * t[0], z0 + path * t[2], path};
}

// 0 or 1: which kind of square of side period/2 a bed point lies on; −1 within `margin` of an
// edge.
int parity(double x, double z, double period, double margin) {
  const double u = 2.0 * x / period, v = 2.0 * z / period;
  const double du = std::abs(u - std::round(u)), dv = std::abs(v - std::round(v));
  if (du < margin || dv < margin) return -1;
  return static_cast<int>(std::floor(u) + std::floor(v)) & 1;
}

std::vector<float> bed_draw(Rig& rig, const View& view) {
  EXPECT_TRUE(rig.renderer->draw(view).ok());
  std::vector<float> hdr;
  EXPECT_TRUE(rig.renderer->read_hdr(hdr).ok());
  return hdr;
}

TEST(Seabed, ACheckerAppearsWhereRefractionPutsIt) {
  auto rig = make_bed_rig();
  if (rig == nullptr) OCEAN_SKIP_OR_FAIL("no Vulkan device");
  const View view = straight_down(3.0, 1.0);
  const std::vector<float> hdr = bed_draw(*rig, view);
  // Luminance threshold between the two squares' levels: the mean of the picture.
  double mean = 0.0;
  for (int i = 0; i < kBedW * kBedH; ++i) mean += hdr[static_cast<std::size_t>(4 * i + 1)];
  mean /= kBedW * kBedH;
  const auto agreement = [&](bool refract) {
    int same[2] = {0, 0}, counted = 0;
    for (int y = 0; y < kBedH; ++y)
      for (int x = 0; x < kBedW; ++x) {
        const BedHit h = bed_point(view, x, y, refract);
        const int p = parity(h.x, h.z, 1.0, 0.08);  // a pixel spans < 0.04 squares here
        if (p < 0) continue;
        const int light = hdr[static_cast<std::size_t>(4 * (y * kBedW + x) + 1)] > mean ? 1 : 0;
        ++counted;
        ++same[light == p ? 1 : 0];
      }
    return static_cast<double>(std::max(same[0], same[1])) / counted;  // up to a swap of colours
  };
  EXPECT_GT(agreement(true), 0.99);
  EXPECT_LT(agreement(false), 0.9);  // the geometry without refraction does not fit
}

TEST(Seabed, ContrastFadesWithDepthAsBeerLambertStates) {
  auto rig = make_bed_rig();
  if (rig == nullptr) OCEAN_SKIP_OR_FAIL("no Vulkan device");
  const double period = 4.0, d1 = 2.0, d2 = 6.0;
  // The light minus the dark squares' mean radiance, per channel, near the picture's centre
  // (the camera is above a corner of four squares; the path there is the depth within 0.1 %).
  const auto contrast = [&](double depth) {
    const View view = straight_down(depth, period);
    const std::vector<float> hdr = bed_draw(*rig, view);
    std::array<double, 3> sum[2]{};
    int n[2] = {0, 0};
    for (int y = kBedH / 2 - 8; y < kBedH / 2 + 8; ++y)
      for (int x = kBedW / 2 - 8; x < kBedW / 2 + 8; ++x) {
        const BedHit h = bed_point(view, x, y, true);
        const int p = parity(h.x, h.z, period, 0.12);  // beyond the filter (≈ 2 pixels)
        if (p < 0) continue;
        ++n[p];
        for (std::size_t c = 0; c < 3; ++c)
          sum[p][c] += hdr[static_cast<std::size_t>(4 * (y * kBedW + x)) + c];
      }
    EXPECT_GT(n[0], 20);
    EXPECT_GT(n[1], 20);
    std::array<double, 3> out{};
    for (std::size_t c = 0; c < 3; ++c) out[c] = std::abs(sum[1][c] / n[1] - sum[0][c] / n[0]);
    return out;
  };
  const std::array<double, 3> c1 = contrast(d1), c2 = contrast(d2);
  // R.23 straight down: contrast ∝ (A·e^{−a·d/μ_w} + B·e^{−a·d})·e^{−a·d}, A the sun's
  // irradiance through the surface, B the sky's, μ_w the refracted sun's cosine.
  const View view = straight_down(d1, period);
  const Sky sky(view.shading);
  const std::array<double, 3> sun = sky.sun_irradiance_ground(),
                              sky_e = sky.sky_irradiance_horizontal();
  const double mu_s = std::sin(45.0 * std::numbers::pi / 180.0);
  const double fresnel = 0.02 + 0.98 * std::pow(1.0 - mu_s, 5.0);
  const double sin_w = std::sqrt(1.0 - mu_s * mu_s) / kIor, mu_w = std::sqrt(1.0 - sin_w * sin_w);
  for (std::size_t c = 0; c < 3; ++c) {
    const double a = view.seabed.absorption_per_m[c];
    const auto light = [&](double d) {
      return (sun[c] * mu_s * (1.0 - fresnel) * std::exp(-a * d / mu_w) +
              sky_e[c] * std::exp(-a * d)) *
             std::exp(-a * d);
    };
    EXPECT_NEAR(c2[c] / c1[c], light(d2) / light(d1), 0.03 * light(d2) / light(d1))
        << "channel " << c;
  }
  // Red fades most: pure water absorbs red 37 times more than blue.
  EXPECT_LT(c2[0] / c1[0], 0.1);
  EXPECT_GT(c2[2] / c1[2], 0.9);
}

// A bathymetry under the flat bed (R.52): where its grid covers the water the bed lies at the
// map's depth — the picture of a 6 m bed under a grid that says 2 m is the picture of a flat 2 m
// bed, shallow water's tint (R.24) not added twice — and outside the grid at the flat depth.
TEST(Seabed, TheBathymetrysDepthReplacesTheFlatBeds) {
  auto rig = make_bed_rig();
  if (rig == nullptr) OCEAN_SKIP_OR_FAIL("no Vulkan device");
  const std::vector<float> flat2 = bed_draw(*rig, straight_down(2.0, 1.0));
  const std::vector<float> flat6 = bed_draw(*rig, straight_down(6.0, 1.0));
  constexpr int kN = 4;
  const std::vector<float> weights(kDampingBands * kN * kN, 1.0f), depth(kN * kN, 2.0f);
  const auto mean_difference = [](const std::vector<float>& a, const std::vector<float>& b) {
    double sum = 0.0, level = 0.0;
    for (std::size_t i = 0; i < a.size(); ++i) {
      if (i % 4 == 3) continue;
      sum += std::abs(a[i] - b[i]);
      level += std::abs(b[i]);
    }
    return sum / level;  // relative to the reference's mean
  };
  ASSERT_GT(mean_difference(flat6, flat2), 0.2);  // the two depths look apart
  // The grid over the whole picture, then a grid far away.
  for (const double origin : {-100.0, 1000.0}) {
    ASSERT_TRUE(rig->renderer
                    ->set_damping({.origin_m = {origin, origin},
                                   .size_m = 200.0,
                                   .resolution = kN,
                                   .band_weights = weights,
                                   .depth_m = depth})
                    .ok());
    const std::vector<float> mapped = bed_draw(*rig, straight_down(6.0, 1.0));
    EXPECT_LT(mean_difference(mapped, origin < 0.0 ? flat2 : flat6), 0.01) << origin;
  }
}

}  // namespace
