// The renderer on any Vulkan device (lavapipe on CPU-only machines), with the Khronos
// validation layer on and zero messages asserted: small images checked with robust statistics —
// sky above the horizon and water below, no NaN or black pixels, change when time advances,
// foam only where the Jacobian is low, the CPU upload path and the zero-copy Vulkan path giving
// the same picture — plus the sky model against its physics and bad input. Skips where no
// Vulkan device exists (fails with OCEAN_REQUIRE_DEVICES=1).
#include "ocean/render.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>
#include <vector>

#include "ocean/backends.hpp"
#include "ocean/backends/vulkan.hpp"
#include "render/render_helpers.hpp"
#include "support/require_devices.hpp"

namespace {

using ocean::render::DebugView;
using ocean::render::Renderer;
using ocean::render::View;
using ocean::render::testing::eye_level_view;
using ocean::render::testing::graphics_context;
using ocean::render::testing::small_config;

constexpr double kRenderPi = std::numbers::pi;

struct BareRig {
  std::shared_ptr<ocean::vk::Context> ctx;
  std::unique_ptr<ocean::Simulator> sim;
  std::unique_ptr<Renderer> renderer;
  ocean::vk::VulkanBackend* gpu = nullptr;

  // Simulates time t and hands the frame to the renderer.
  void step(double t) {
    sim->step(t);
    if (gpu != nullptr) {
      ASSERT_TRUE(gpu->status().ok()) << gpu->status().message();
      ASSERT_TRUE(renderer->use_simulation_images(gpu->images(), sim->frame()).ok());
    } else {
      ASSERT_TRUE(renderer->upload(sim->frame()).ok());
    }
  }
  ~BareRig() {
    if (ctx != nullptr) {
      EXPECT_EQ(ctx->validation_messages.load(), 0u) << ctx->last_validation_message;
    }
  }
};

// A rig on a validated graphics context; `gpu` selects the Vulkan backend on that context.
std::unique_ptr<BareRig> make_rig(const ocean::SimulationConfig& config, int w, int h, bool gpu) {
  auto rig = std::make_unique<BareRig>();
  rig->ctx = graphics_context();
  if (rig->ctx == nullptr) return nullptr;
  std::unique_ptr<ocean::Backend> backend;
  if (gpu) {
    auto b = std::make_unique<ocean::vk::VulkanBackend>(rig->ctx);
    rig->gpu = b.get();
    backend = std::move(b);
  } else {
    backend = std::move(ocean::make_backend("cpu")).value();
  }
  auto sim = ocean::Simulator::make(config, std::move(backend));
  EXPECT_TRUE(sim.ok()) << sim.status().message();
  if (!sim.ok()) return nullptr;
  rig->sim = std::move(sim).value();
  auto r = Renderer::make(rig->ctx, {.width = w, .height = h});
  EXPECT_TRUE(r.ok()) << r.status().message();
  if (!r.ok()) return nullptr;
  rig->renderer = std::move(r).value();
  EXPECT_TRUE(rig->renderer->configure(ocean::SimulationPlan::make(config).value().surface()).ok());
  return rig;
}

#define REQUIRE_RIG(rig)                                                       \
  if ((rig) == nullptr) {                                                      \
    if (graphics_context() == nullptr) OCEAN_SKIP_OR_FAIL("no Vulkan device"); \
    FAIL() << "could not build the renderer";                                  \
  }

struct Image {
  int w = 0, h = 0;
  std::vector<float> rgba;  // linear HDR
  [[nodiscard]] const float* at(int x, int y) const {
    return &rgba[static_cast<std::size_t>(4 * (y * w + x))];
  }
};

Image render_hdr(BareRig& rig, const View& view) {
  Image im{rig.renderer->width(), rig.renderer->height(), {}};
  const ocean::Status drawn = rig.renderer->draw(view);
  EXPECT_TRUE(drawn.ok()) << drawn.message();
  EXPECT_TRUE(rig.renderer->read_hdr(im.rgba).ok());
  return im;
}

// Mean of one channel over rows [y0, y1).
double mean_rows(const Image& im, int y0, int y1, int channel) {
  double sum = 0.0;
  for (int y = y0; y < y1; ++y)
    for (int x = 0; x < im.w; ++x) sum += im.at(x, y)[channel];
  return sum / ((y1 - y0) * im.w);
}

TEST(Sky, AirMassMatchesKastenYoung) {
  EXPECT_NEAR(ocean::render::air_mass(1.0), 1.0, 1e-3);
  // Kasten & Young (1989), Table/eq.: m(90°) ≈ 37.92; m(60°) ≈ 1.994.
  EXPECT_NEAR(ocean::render::air_mass(0.0), 37.92, 0.05);
  EXPECT_NEAR(ocean::render::air_mass(0.5), 1.9942, 0.002);
}

TEST(Sky, RayleighMakesTheSkyBlueAndTheLowSunRed) {
  ocean::render::ShadingParams p;
  p.sun_elevation_deg = 40.0;
  p.sun_azimuth_deg = 0.0;
  const ocean::render::Sky sky(p);
  // Away from the sun, the zenith is blue: B > G > R.
  const auto zenith = sky.radiance({0.0, 1.0, 0.0});
  EXPECT_GT(zenith[2], zenith[1]);
  EXPECT_GT(zenith[1], zenith[0]);
  // The horizon is brighter and whiter than the zenith (longer path, saturated scattering).
  const auto horizon = sky.radiance({-1.0, 0.0, 0.0});
  EXPECT_GT(horizon[1], zenith[1]);
  EXPECT_LT(horizon[2] / horizon[0], zenith[2] / zenith[0]);
  // Symmetric about the sun's vertical plane; brighter towards the sun (forward scattering).
  const auto left = sky.radiance({0.5, 0.5, 0.7071});
  const auto right = sky.radiance({0.5, 0.5, -0.7071});
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(left[c], right[c], 1e-12);
  const auto towards = sky.radiance({0.7071, 0.3, 0.0});
  const auto away = sky.radiance({-0.7071, 0.3, 0.0});
  EXPECT_GT(towards[1], away[1]);
  // A low sun is dimmer and redder at sea level than a high one.
  p.sun_elevation_deg = 5.0;
  const ocean::render::Sky low(p);
  const auto high_e = sky.sun_irradiance_ground(), low_e = low.sun_irradiance_ground();
  EXPECT_LT(low_e[1], high_e[1]);
  EXPECT_GT(low_e[0] / low_e[2], high_e[0] / high_e[2]);
  // Transmittance at the zenith sun is exp(−τ): Rayleigh τ_B = 33.1e-6·8000 plus haze.
  p.sun_elevation_deg = 90.0;
  const ocean::render::Sky top(p);
  EXPECT_NEAR(top.sun_irradiance_ground()[2] / p.sun_irradiance,
              std::exp(-(33.1e-6 * 8000.0 + 2e-5 * 1200.0)), 2e-3);
}

TEST(Sky, SkyIrradianceIsTheCosineWeightedIntegral) {
  // For a sky of uniform radiance L the horizontal irradiance is π·L; check the quadrature on
  // the real sky against a finer sum of the same integrand.
  ocean::render::ShadingParams p;
  const ocean::render::Sky sky(p);
  const auto e = sky.sky_irradiance_horizontal();
  double fine = 0.0;
  const int n = 200;
  for (int i = 0; i < n; ++i) {
    const double el = (i + 0.5) / n * kRenderPi / 2.0;
    for (int j = 0; j < 2 * n; ++j) {
      const double az = (j + 0.5) / (2 * n) * 2.0 * kRenderPi;
      const auto l =
          sky.radiance({std::cos(el) * std::cos(az), std::sin(el), std::cos(el) * std::sin(az)});
      fine += l[1] * std::sin(el) * std::cos(el) * (kRenderPi / 2.0 / n) * (kRenderPi / n);
    }
  }
  EXPECT_NEAR(e[1], fine, 0.03 * fine);
}

// Aerial perspective (R.8b) against exact identities of the plane-parallel exponential
// atmosphere: the whole column straight up transmits what reaches sea level from a zenith sun
// (air mass 1, R.3); a short horizontal path at height y has the optical depth β(y)·d of
// constant density; no path, no change; the in-scattered light grows with the path and stays
// below the light that reaches sea level.
TEST(Sky, AerialPerspectiveMatchesTheColumnsOpticalDepth) {
  ocean::render::ShadingParams p;
  p.sun_elevation_deg = 90.0;
  const ocean::render::Sky zenith(p);
  const auto column = zenith.aerial_perspective(1e6, 0.0, 1e6, {0.0, -1.0, 0.0});
  const auto ground = zenith.sun_irradiance_ground();
  const ocean::render::Sky::Air column_air = zenith.air();
  for (std::size_t c = 0; c < 3; ++c) {
    const double tau = column_air.rayleigh_per_m[c] * column_air.rayleigh_height_m +
                       column_air.mie_per_m * column_air.mie_height_m;
    EXPECT_NEAR(column.transmittance[c], std::exp(-tau), 1e-12) << c;
    // Kasten–Young's air mass at the zenith is 0.9997, not 1: the sun's path is 3·10⁻⁴ shorter.
    EXPECT_NEAR(column.transmittance[c], ground[c] / p.sun_irradiance, 1e-4) << c;
  }

  p.sun_elevation_deg = 20.0;
  const ocean::render::Sky sky(p);
  const ocean::render::Sky::Air air = sky.air();
  const auto flat = sky.aerial_perspective(3000.0, 3000.0, 500.0, {1.0, 0.0, 0.0});
  for (std::size_t c = 0; c < 3; ++c) {
    const double tau = 500.0 * (air.rayleigh_per_m[c] * std::exp(-3000.0 / air.rayleigh_height_m) +
                                air.mie_per_m * std::exp(-3000.0 / air.mie_height_m));
    EXPECT_NEAR(flat.transmittance[c], std::exp(-tau), 1e-9) << c;
  }
  const auto none = sky.aerial_perspective(20.0, 0.0, 0.0, {0.0, -1.0, 0.0});
  const auto near = sky.aerial_perspective(3000.0, 0.0, 3000.0, {0.0, -1.0, 0.0});
  const auto far = sky.aerial_perspective(10000.0, 0.0, 10000.0, {0.0, -1.0, 0.0});
  const auto sun_ground = sky.sun_irradiance_ground();
  for (std::size_t c = 0; c < 3; ++c) {
    EXPECT_EQ(none.transmittance[c], 1.0);
    EXPECT_EQ(none.inscattered[c], 0.0);
    EXPECT_GT(far.inscattered[c], near.inscattered[c]);
    EXPECT_LT(far.transmittance[c], near.transmittance[c]);
    EXPECT_LT(far.inscattered[c], sun_ground[c]);
  }
  // Rayleigh: the air's light is bluest, its transmittance reddest.
  EXPECT_GT(far.inscattered[2], far.inscattered[0]);
  EXPECT_LT(far.transmittance[2], far.transmittance[0]);
}

TEST(Renderer, SkyAboveTheHorizonWaterBelowNoNanOrBlackPixels) {
  const int w = 160, h = 90;
  auto rig = make_rig(small_config(), w, h, false);
  REQUIRE_RIG(rig);
  rig->step(3.0);
  const View view = eye_level_view(w, h);
  const Image im = render_hdr(*rig, view);
  ASSERT_EQ(im.rgba.size(), static_cast<std::size_t>(w * h * 4));
  for (float v : im.rgba) ASSERT_TRUE(std::isfinite(v));
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const float* p = im.at(x, y);
      ASSERT_GT(p[0] + p[1] + p[2], 1e-4f) << "black pixel at " << x << "," << y;
    }
  // Top quarter: sky, blue over red. Bottom quarter: water, darker than the sky.
  const double sky_b = mean_rows(im, 0, h / 4, 2), sky_r = mean_rows(im, 0, h / 4, 0);
  EXPECT_GT(sky_b, sky_r);
  const double sky_g = mean_rows(im, 0, h / 4, 1);
  const double water_g = mean_rows(im, 3 * h / 4, h, 1);
  EXPECT_LT(water_g, sky_g);
  // The water's colour varies (waves), the sky's top rows are smooth.
  double lo = 1e9, hi = 0.0;
  for (int y = 3 * h / 4; y < h; ++y)
    for (int x = 0; x < w; ++x)
      lo = std::min(lo, double(im.at(x, y)[1])), hi = std::max(hi, double(im.at(x, y)[1]));
  EXPECT_GT(hi, 1.5 * lo);
  const auto& s = rig->renderer->stats();
  EXPECT_GT(s.patches, 0u);
  EXPECT_LE(s.draw_calls, 16u + 3u);  // ≤ 16 instanced patch draws, skirt, sky, tone map
  EXPECT_GT(s.triangles, 0u);
}

TEST(Renderer, TheSurfaceMovesWhenTimeAdvancesAndTheSkyStays) {
  const int w = 128, h = 72;
  auto rig = make_rig(small_config(), w, h, false);
  REQUIRE_RIG(rig);
  const View view = eye_level_view(w, h);
  rig->step(1.0);
  const Image a = render_hdr(*rig, view);
  rig->step(1.5);
  const Image b = render_hdr(*rig, view);
  double water = 0.0, sky = 0.0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const double d = std::abs(a.at(x, y)[1] - b.at(x, y)[1]);
      if (y < h / 4) sky += d;
      if (y >= 5 * h / 8) water += d;
    }
  EXPECT_EQ(sky, 0.0);
  EXPECT_GT(water / (w * 3 * h / 8), 1e-3);
}

TEST(Renderer, FoamOnlyWhereTheJacobianIsLow) {
  // Looking straight down from 200 m at a storm sea with foam accumulation off, so foam is a
  // function of the present Jacobian (M.7.4). Each pixel maps to a world point (x, z) at sea
  // level; the height query gives the undisplaced point that lands there, where the CPU frame
  // tells J. The foam's contribution (image minus the same image without foam) must sit where
  // J < J_start.
  ocean::SimulationConfig c;
  c.resolution = 64;
  c.cascade_patch_sizes_m = {100.0};
  c.sea.wind_sea.spectrum.wind_speed_mps = 20.0;
  c.sea.wind_sea.spectrum.fetch_m = 300e3;
  c.choppiness = 1.3;
  c.foam = {.source = ocean::FoamSource::ramp,
            .jacobian_start = 0.9,
            .jacobian_full = 0.6,
            .decay_per_s = 1e6};
  const int n = 96;
  auto rig = make_rig(c, n, n, false);
  REQUIRE_RIG(rig);
  // The foam where the map holds it: the wind drift's footprint (docs/waves.md W.31) draws it
  // downwind of where J is low, which tests/render/foam_streaks_render_test.cpp measures.
  ocean::SurfaceDescription surface = ocean::SimulationPlan::make(c).value().surface();
  surface.foam_drift_mps = {0.0, 0.0};
  ASSERT_TRUE(rig->renderer->configure(surface).ok());
  rig->step(7.0);
  View view = eye_level_view(n, n);
  const double height = 200.0, fov = 2.0 * std::atan(24.0 / height);  // 48 m across
  view.camera = {.position_m = {30.0, height, 40.0},
                 .target_m = {30.0, 0.0, 40.0},
                 .fov_y_rad = fov,
                 .aspect = 1.0,
                 .near_m = 1.0,
                 .far_m = 1e4};
  view.shading.sun_elevation_deg = 60.0;
  const Image with = render_hdr(*rig, view);
  view.shading.foam_brightness = 0.0;
  const Image without = render_hdr(*rig, view);
  // Straight down, image right is +x and image down is +z (lod::look_at).
  const double metres_per_pixel = 2.0 * height * std::tan(fov / 2.0) / n;
  std::vector<std::array<double, 2>> xz;
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x)
      xz.push_back({30.0 + (x + 0.5 - n / 2.0) * metres_per_pixel,
                    40.0 + (y + 0.5 - n / 2.0) * metres_per_pixel});
  std::vector<ocean::HeightSample> samples(xz.size());
  rig->sim->heights_at(xz, samples);
  const ocean::CascadeFrame& f = rig->sim->frame().cascades[0];
  const auto jacobian_at = [&](double sx, double sz) {  // bilinear, wrapped, as the GPU samples
    const double u = sx / 100.0 * 64.0, v = sz / 100.0 * 64.0;
    const double fu = std::floor(u), fv = std::floor(v);
    double j = 0.0;
    for (int dy = 0; dy < 2; ++dy)
      for (int dx = 0; dx < 2; ++dx) {
        const int col = ((static_cast<int>(fu) + dx) % 64 + 64) % 64;
        const int row = ((static_cast<int>(fv) + dy) % 64 + 64) % 64;
        const double wgt = (dx ? u - fu : 1.0 - (u - fu)) * (dy ? v - fv : 1.0 - (v - fv));
        j += wgt * f.jacobian[static_cast<std::size_t>(row * 64 + col)];
      }
    return j;
  };
  int foamy = 0, foamy_low_j = 0, high_j = 0, high_j_foamy = 0;
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      const double d = with.at(x, y)[1] - without.at(x, y)[1];
      const auto& s = samples[static_cast<std::size_t>(y * n + x)];
      const double j = jacobian_at(s.source_xz[0], s.source_xz[1]);
      const bool foam = d > 0.05 * with.at(x, y)[1];
      if (foam) ++foamy, foamy_low_j += j < c.foam.jacobian_start + 0.05 ? 1 : 0;
      if (j > c.foam.jacobian_start + 0.1) ++high_j, high_j_foamy += foam ? 1 : 0;
    }
  ASSERT_GT(foamy, n * n / 100) << "no foam to test";
  ASSERT_GT(high_j, n * n / 4);
  EXPECT_GE(foamy_low_j, 0.9 * foamy) << foamy_low_j << " of " << foamy;
  EXPECT_LE(high_j_foamy, 0.03 * high_j) << high_j_foamy << " of " << high_j;
}

TEST(Renderer, VulkanBackendImagesGiveTheCpuPicture) {
  const int w = 128, h = 72;
  const ocean::SimulationConfig config = small_config();
  auto cpu = make_rig(config, w, h, false);
  REQUIRE_RIG(cpu);
  auto gpu = make_rig(config, w, h, true);
  REQUIRE_RIG(gpu);
  const View view = eye_level_view(w, h);
  cpu->step(2.0);
  gpu->step(2.0);
  const Image a = render_hdr(*cpu, view);
  const Image b = render_hdr(*gpu, view);
  std::vector<std::uint8_t> sa, sb;
  ASSERT_TRUE(cpu->renderer->read_srgb(sa).ok());
  ASSERT_TRUE(gpu->renderer->read_srgb(sb).ok());
  ASSERT_EQ(sa.size(), sb.size());
  const ocean::render::testing::PictureDifference d = ocean::render::testing::difference(sa, sb);
  // Same maps within the conformance bounds (ocean/conformance.hpp: RGBA8 within 1 LSB,
  // displacement within a few 1e-6·Hs): the pictures agree to within rounding. Distant water
  // shows every cascade's filtered normals (R.5), where the sun's GGX lobe at α ≈ 0.1 turns one
  // LSB of a normal (1/127 of slope) into up to ~10 LSB of a glitter pixel.
  EXPECT_LE(d.mean, 0.05);
  EXPECT_LE(d.max, 12);
}

TEST(Renderer, DebugViewsAndResizing) {
  const int w = 96, h = 54;
  auto rig = make_rig(small_config(), w, h, false);
  REQUIRE_RIG(rig);
  rig->step(1.0);
  View view = eye_level_view(w, h);
  const Image shaded = render_hdr(*rig, view);
  view.debug = DebugView::lod_colours;
  const Image coloured = render_hdr(*rig, view);
  double d = 0.0;
  for (std::size_t i = 0; i < shaded.rgba.size(); ++i)
    d += std::abs(shaded.rgba[i] - coloured.rgba[i]);
  EXPECT_GT(d, 1.0);
  if (rig->ctx->wireframe) {
    view.debug = DebugView::wireframe;
    const Image wire = render_hdr(*rig, view);
    // Lines over the sky: the lower half is mostly sky-coloured gaps with dark edges.
    EXPECT_NE(wire.rgba, shaded.rgba);
  }
  ASSERT_TRUE(rig->renderer->resize(64, 40).ok());
  view.camera.aspect = 64.0 / 40.0;
  view.debug = DebugView::shaded;
  const Image small = render_hdr(*rig, view);
  EXPECT_EQ(small.w, 64);
  EXPECT_EQ(small.h, 40);
  // Quality changes rebuild the patch meshes.
  view.quality = ocean::lod::quality_preset(ocean::lod::QualityPreset::high);
  const Image high = render_hdr(*rig, view);
  EXPECT_GT(rig->renderer->stats().triangles, 0u);
  EXPECT_EQ(high.rgba.size(), small.rgba.size());
}

TEST(Renderer, BadInputIsRefusedWithAMessage) {
  auto compute_only = ocean::vk::create_context({});
  if (!compute_only.ok()) OCEAN_SKIP_OR_FAIL("no Vulkan device");
  auto r = Renderer::make(std::shared_ptr<ocean::vk::Context>(std::move(compute_only).value()), {});
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.status().code(), ocean::ErrorCode::unsupported);
  EXPECT_NE(r.status().message().find("graphics"), std::string::npos);

  auto rig = make_rig(small_config(), 32, 32, false);
  REQUIRE_RIG(rig);
  EXPECT_EQ(rig->renderer->resize(0, 10).code(), ocean::ErrorCode::invalid_argument);
  EXPECT_EQ(rig->renderer->resize(10, 20000).code(), ocean::ErrorCode::invalid_argument);
  View view = eye_level_view(32, 32);
  view.camera.position_m.x = std::nan("");
  EXPECT_EQ(rig->renderer->draw(view).code(), ocean::ErrorCode::invalid_argument);
  view = eye_level_view(32, 32);
  view.shading.exposure = -1.0;
  const ocean::Status s = rig->renderer->draw(view);
  EXPECT_EQ(s.code(), ocean::ErrorCode::invalid_argument);
  EXPECT_NE(s.message().find("exposure"), std::string::npos) << s.message();
  view = eye_level_view(32, 32);
  view.ocean_size_m = 100.0;
  EXPECT_EQ(rig->renderer->draw(view).code(), ocean::ErrorCode::invalid_argument);
  ocean::Frame wrong;
  ocean::SimulationConfig other = small_config();
  other.cascade_patch_sizes_m = {100.0};
  ocean::allocate_frame(other, wrong);
  EXPECT_EQ(rig->renderer->upload(wrong).code(), ocean::ErrorCode::invalid_argument);
  EXPECT_FALSE(ocean::render::parse_debug_view("xray").ok());
}

TEST(RenderNames, UnknownNamesAreEchoedOnOneLine) {
  EXPECT_EQ(ocean::render::parse_debug_view("x\nray").status().message(),
            "view = x\\nray is not a view: must be shaded, lod, wireframe or normals");
  EXPECT_EQ(ocean::render::sky_preset("fog\ngy").status().message(),
            "sky = fog\\ngy is not a sky: must be clear, hazy, overcast or sunset");
}

}  // namespace
#undef REQUIRE_RIG
