// Stereo in one pass (docs/rendering.md R.25) on any Vulkan device with multiview (lavapipe on
// CPU-only machines), validation layer on:
// - stereo_eyes: the eyes ∓IPD/2 along the head's right axis, looking the same way; a negative
//   or NaN IPD refused;
// - each half of a side-by-side stereo picture equals a mono picture from that eye's pose: at
//   IPD 0 exactly (the multiview shaders compute what the mono ones do), at 64 mm within 1 LSB
//   mean and 99.5 % of the values within 2 LSB (the eyes share the head's LOD selection, which
//   a mono render from the eye can refine differently where a patch is within 32 mm of a
//   split distance);
// - a headset's eyes (rolled, canted, asymmetric fields of view) drawn in one pass: each half
//   equals a mono picture from that eye bit for bit;
// - a context without multiview and an odd width refused with one line.
// Skips where no Vulkan device exists (fails with OCEAN_REQUIRE_DEVICES=1).
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <memory>
#include <numbers>
#include <span>
#include <vector>

#include "ocean/backends.hpp"
#include "ocean/render.hpp"
#include "render/render_helpers.hpp"
#include "support/require_devices.hpp"

namespace {

using ocean::render::Renderer;
using ocean::render::View;
using ocean::render::testing::graphics_context;

constexpr int kEyeW = 96, kEyeH = 64;

struct StereoRig {
  std::shared_ptr<ocean::vk::Context> ctx;
  std::unique_ptr<ocean::Simulator> sim;
  ~StereoRig() {
    if (ctx != nullptr) {
      EXPECT_EQ(ctx->validation_messages.load(), 0u) << ctx->last_validation_message;
    }
  }
  // A renderer of w × h with the simulation's frame at t = 3 s.
  std::unique_ptr<Renderer> renderer(int w, int h) const {
    auto r = Renderer::make(ctx, {.width = w, .height = h});
    if (!r.ok()) return nullptr;
    const ocean::SimulationConfig config = ocean::render::testing::small_config();
    if (!r.value()->configure(ocean::SimulationPlan::make(config).value().surface()).ok() ||
        !r.value()->upload(sim->frame()).ok())
      return nullptr;
    return std::move(r).value();
  }
};

std::unique_ptr<StereoRig> make_rig() {
  auto rig = std::make_unique<StereoRig>();
  rig->ctx = graphics_context();
  if (rig->ctx == nullptr) return nullptr;
  auto sim = ocean::Simulator::make(ocean::render::testing::small_config(),
                                    std::move(ocean::make_backend("cpu")).value());
  if (!sim.ok()) return nullptr;
  rig->sim = std::move(sim).value();
  rig->sim->step(3.0);
  return rig;
}

#define REQUIRE_RIG(rig)                                                       \
  if ((rig) == nullptr) {                                                      \
    if (graphics_context() == nullptr) OCEAN_SKIP_OR_FAIL("no Vulkan device"); \
    FAIL() << "could not build the simulation";                                \
  }

// The left (eye 0) or right (eye 1) half of a side-by-side RGBA8 picture.
std::vector<std::uint8_t> half(const std::vector<std::uint8_t>& rgba, int eye) {
  std::vector<std::uint8_t> out;
  for (int y = 0; y < kEyeH; ++y) {
    const auto row = static_cast<std::size_t>(4 * (y * 2 * kEyeW + eye * kEyeW));
    out.insert(out.end(), rgba.begin() + static_cast<std::ptrdiff_t>(row),
               rgba.begin() + static_cast<std::ptrdiff_t>(row + 4 * kEyeW));
  }
  return out;
}

// Share of the values of two pictures that differ by more than `lsb`.
double share_above(const std::vector<std::uint8_t>& a, const std::vector<std::uint8_t>& b,
                   int lsb) {
  std::size_t n = 0;
  for (std::size_t i = 0; i < a.size(); ++i) n += std::abs(int(a[i]) - int(b[i])) > lsb ? 1 : 0;
  return static_cast<double>(n) / static_cast<double>(a.size());
}

TEST(StereoEyes, OffsetAlongTheHeadsRightAxis) {
  const ocean::lod::Camera head{.position_m = {10.0, 5.0, 0.0}, .target_m = {10.0, 5.0, -100.0}};
  const auto eyes = ocean::render::stereo_eyes(head, 0.064);
  ASSERT_TRUE(eyes.ok()) << eyes.status().message();
  // Looking along −z, right is +x (forward × up).
  EXPECT_DOUBLE_EQ(eyes.value()[0].position_m.x, 10.0 - 0.032);
  EXPECT_DOUBLE_EQ(eyes.value()[1].position_m.x, 10.0 + 0.032);
  for (const auto& e : eyes.value()) {
    EXPECT_DOUBLE_EQ(e.position_m.y, 5.0);
    EXPECT_DOUBLE_EQ(e.target_m.x - e.position_m.x, 0.0);  // parallel axes
    EXPECT_DOUBLE_EQ(e.target_m.z, -100.0);
  }
  for (double bad :
       {-0.01, std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()}) {
    const auto r = ocean::render::stereo_eyes(head, bad);
    ASSERT_FALSE(r.ok()) << bad;
    EXPECT_NE(r.status().message().find("IPD"), std::string::npos) << r.status().message();
  }
}

// Draws `head` in stereo and each eye in mono; returns per eye the difference and the share of
// values more than 2 LSB apart. `both` receives the side-by-side picture.
struct EyeDifference {
  ocean::render::testing::PictureDifference d;
  double above_2 = 0.0;
};
std::array<EyeDifference, 2> stereo_against_mono(Renderer& stereo, Renderer& mono, const View& head,
                                                 const std::array<ocean::lod::Camera, 2>& eyes,
                                                 double ipd, std::vector<std::uint8_t>& both) {
  std::array<EyeDifference, 2> out{};
  const ocean::Status drawn = stereo.draw_stereo(head, eyes);
  EXPECT_TRUE(drawn.ok()) << drawn.message();
  EXPECT_TRUE(stereo.read_srgb(both).ok());
  EXPECT_EQ(both.size(), static_cast<std::size_t>(2 * kEyeW * kEyeH * 4));
  for (std::size_t e = 0; e < 2 && both.size() == 2 * kEyeW * kEyeH * 4; ++e) {
    View v = head;
    v.camera = eyes[e];
    v.object_reflections = false;  // the stereo pass mirrors no object (R.53)
    EXPECT_TRUE(mono.draw(v).ok());
    std::vector<std::uint8_t> one;
    EXPECT_TRUE(mono.read_srgb(one).ok());
    const std::vector<std::uint8_t> left_or_right = half(both, static_cast<int>(e));
    out[e] = {ocean::render::testing::difference(left_or_right, one),
              share_above(left_or_right, one, 2)};
    std::printf("IPD %.3f, τ %g: eye %zu differs from mono by %.4f LSB mean, %d max, %.3f %% > 2\n",
                ipd, head.quality.lod_scale, e, out[e].d.mean, out[e].d.max,
                100.0 * out[e].above_2);
  }
  return out;
}

// A view without the whitecaps' patches (R.11b): their edge is a step about as wide as the
// field's change across a pixel, which turns a last-bit difference between the multiview and the
// mono vertex paths' world positions into a level of the 8-bit picture; the bit-for-bit
// comparisons below are of everything else.
View no_patches(View view) {
  view.shading.whitecap_patches = false;
  return view;
}

// A 4 m cube (the object pass draws in stereo as well).
ocean::render::Mesh cube() {
  std::vector<std::array<double, 3>> v;
  for (int i = 0; i < 8; ++i)
    v.push_back({i & 1 ? 2.0 : -2.0, i & 2 ? 2.0 : -2.0, i & 4 ? 2.0 : -2.0});
  const std::vector<std::array<std::uint32_t, 3>> t = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6},
                                                       {0, 1, 4}, {1, 5, 4}, {2, 6, 3}, {3, 6, 7},
                                                       {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
  return ocean::render::flat_mesh(v, t, {.base_colour = {0.9, 0.2, 0.02}});
}

TEST(StereoRender, EachEyeEqualsAMonoRenderFromItsPose) {
  auto rig = make_rig();
  REQUIRE_RIG(rig);
  if (!rig->ctx->multiview) GTEST_SKIP() << "the device lacks multiview";
  auto stereo = rig->renderer(2 * kEyeW, kEyeH);
  auto mono = rig->renderer(kEyeW, kEyeH);
  ASSERT_NE(stereo, nullptr);
  ASSERT_NE(mono, nullptr);
  const ocean::render::Mesh box = cube();
  ASSERT_TRUE(stereo->set_meshes(std::span(&box, 1)).ok());
  ASSERT_TRUE(mono->set_meshes(std::span(&box, 1)).ok());
  View head = no_patches(ocean::render::testing::eye_level_view(kEyeW, kEyeH));
  // Away from the lines where the grid centre's snap (L.9) changes, so that the eyes and the
  // head share one grid centre; a box 40 m ahead, a little to the right.
  for (ocean::lod::Vec3* p : {&head.camera.position_m, &head.camera.target_m})
    p->x += 7.3, p->z += 4.1;
  head.objects = {
      {.mesh = 0, .model = ocean::render::model_matrix({-22.0, 4.0, -22.0}, {1, 0, 0, 0})}};
  std::vector<std::uint8_t> both;
  // IPD 0 (both eyes are the head) and 64 mm: each eye bit for bit its mono render.
  for (double ipd : {0.0, ocean::render::kDefaultIpd_m}) {
    const auto eyes = ocean::render::stereo_eyes(head.camera, ipd);
    ASSERT_TRUE(eyes.ok());
    for (const EyeDifference& e :
         stereo_against_mono(*stereo, *mono, head, eyes.value(), ipd, both))
      EXPECT_EQ(e.d.max, 0) << "IPD " << ipd;
  }
  // With the patches: the same but for a level or two where an edge meets a last-bit difference.
  View with_patches = head;
  with_patches.shading.whitecap_patches = true;
  const auto pair = ocean::render::stereo_eyes(head.camera, ocean::render::kDefaultIpd_m);
  ASSERT_TRUE(pair.ok());
  for (const EyeDifference& e : stereo_against_mono(*stereo, *mono, with_patches, pair.value(),
                                                    ocean::render::kDefaultIpd_m, both)) {
    EXPECT_LE(e.d.max, 3);
    EXPECT_LT(e.above_2, 1e-4);
  }
  // The box is in both eyes (orange: red well above blue; the sea and the sky are not).
  for (int e = 0; e < 2; ++e) {
    const std::vector<std::uint8_t> eye = half(both, e);
    int orange = 0;
    for (std::size_t i = 0; i < eye.size(); i += 4) orange += eye[i] > eye[i + 2] + 40 ? 1 : 0;
    EXPECT_GT(orange, 20) << "eye " << e;
  }
  // The two eyes see different pictures (the comparison above is not of one picture twice).
  EXPECT_GT(ocean::render::testing::difference(half(both, 0), half(both, 1)).mean, 0.2);
}

// A headset's eyes (R.27): each rolled with the head by 0.3 rad, canted 3° outwards, with mirrored
// asymmetric fields of view (wider outwards and downwards), 64 mm apart along the rolled head's
// right axis. The hull of both frusta culls the one selection.
std::array<ocean::lod::Camera, 2> headset_eyes(const ocean::lod::Camera& head, double roll_rad) {
  const double c = std::cos(roll_rad), s = std::sin(roll_rad);
  std::array<ocean::lod::Camera, 2> eyes{head, head};
  for (int e = 0; e < 2; ++e) {
    const double side = e == 0 ? -1.0 : 1.0;
    ocean::lod::Camera& eye = eyes[static_cast<std::size_t>(e)];
    // The head looks along −z: its rolled right is (cos θ, sin θ, 0), its up (−sin θ, cos θ, 0).
    eye.position_m.x += side * 0.032 * c, eye.position_m.y += side * 0.032 * s;
    const double cant = side * std::tan(3.0 * std::numbers::pi / 180.0);
    eye.target_m = {eye.position_m.x + cant * c, eye.position_m.y + cant * s,
                    eye.position_m.z - 1.0};
    eye.up = {-s, c, 0.0};
    eye.fov = ocean::lod::FovAngles{.left_rad = e == 0 ? -0.90 : -0.70,
                                    .right_rad = e == 0 ? 0.70 : 0.90,
                                    .up_rad = 0.55,
                                    .down_rad = -0.80};
  }
  return eyes;
}

TEST(StereoRender, HeadsetEyesEachEqualAMonoRenderFromTheirPose) {
  auto rig = make_rig();
  REQUIRE_RIG(rig);
  if (!rig->ctx->multiview) GTEST_SKIP() << "the device lacks multiview";
  auto stereo = rig->renderer(2 * kEyeW, kEyeH);
  auto mono = rig->renderer(kEyeW, kEyeH);
  ASSERT_NE(stereo, nullptr);
  ASSERT_NE(mono, nullptr);
  View head = no_patches(ocean::render::testing::eye_level_view(kEyeW, kEyeH));
  head.camera.position_m = {7.3, 6.0, 4.1};  // clear of the grid centre's snap lines (L.9)
  head.camera.target_m = {7.3, 6.0, 4.1 - 100.0};
  const auto eyes = headset_eyes(head.camera, 0.3);
  std::vector<std::uint8_t> both;
  // Bit for bit, as the parallel eyes above (the head and eyes share the grid centre's snap).
  for (const EyeDifference& e : stereo_against_mono(*stereo, *mono, head, eyes, 0.064, both))
    EXPECT_EQ(e.d.max, 0);
  // An invalid eye is refused, naming it.
  ocean::lod::Camera bad = eyes[1];
  bad.fov->right_rad = -1.0;
  const auto refused = stereo->draw_stereo(head, {eyes[0], bad});
  EXPECT_EQ(refused.code(), ocean::ErrorCode::invalid_argument);
  EXPECT_NE(refused.message().find("right eye: camera.fov.right_rad"), std::string::npos)
      << refused.message();
}

TEST(StereoRender, RefusedWithoutMultiviewOrWithAnOddWidth) {
  auto ctx = ocean::vk::create_context({.validation = true, .graphics = true, .multiview = false});
  if (!ctx.ok()) OCEAN_SKIP_OR_FAIL("no Vulkan device");
  std::shared_ptr<ocean::vk::Context> shared(std::move(ctx).value());
  EXPECT_FALSE(shared->multiview);
  auto r = Renderer::make(shared, {.width = 2 * kEyeW, .height = kEyeH});
  ASSERT_TRUE(r.ok());
  const View head = ocean::render::testing::eye_level_view(kEyeW, kEyeH);
  const ocean::Status s = r.value()->draw_stereo(head, 0.064);
  EXPECT_EQ(s.code(), ocean::ErrorCode::unsupported);
  EXPECT_NE(s.message().find("multiview"), std::string::npos) << s.message();
  EXPECT_EQ(s.message().find('\n'), std::string::npos);

  auto rig = make_rig();
  REQUIRE_RIG(rig);
  if (!rig->ctx->multiview) GTEST_SKIP() << "the device lacks multiview";
  auto odd = rig->renderer(2 * kEyeW + 1, kEyeH);
  ASSERT_NE(odd, nullptr);
  const ocean::Status o = odd->draw_stereo(head, 0.064);
  EXPECT_EQ(o.code(), ocean::ErrorCode::invalid_argument);
  EXPECT_NE(o.message().find("even"), std::string::npos) << o.message();
  EXPECT_EQ(odd->draw_stereo(head, -0.064).code(), ocean::ErrorCode::invalid_argument);
  EXPECT_EQ(shared->validation_messages.load(), 0u) << shared->last_validation_message;
}

}  // namespace
#undef REQUIRE_RIG
