// Camera matrices and frustum planes (Vulkan depth range) and the AABB test (eqs. 59–60).
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <numbers>

#include "ocean/lod.hpp"

namespace {

using namespace ocean::lod;

std::array<double, 4> transform(const Mat4& m, Vec3 p) {
  std::array<double, 4> r{};
  for (int row = 0; row < 4; ++row) {
    r[static_cast<std::size_t>(row)] =
        m.m[static_cast<std::size_t>(row)] * p.x + m.m[static_cast<std::size_t>(4 + row)] * p.y +
        m.m[static_cast<std::size_t>(8 + row)] * p.z + m.m[static_cast<std::size_t>(12 + row)];
  }
  return r;
}

bool inside(const Frustum& f, Vec3 p) { return box_visible(f, p, {0.0, 0.0, 0.0}); }

TEST(LodFrustum, LookAtAndPerspectiveFollowTheConventions) {
  const Mat4 view = look_at({1.0, 2.0, 3.0}, {1.0, 2.0, -7.0});
  const auto eye = transform(view, {1.0, 2.0, 3.0});
  EXPECT_NEAR(eye[0], 0.0, 1e-12);
  EXPECT_NEAR(eye[2], 0.0, 1e-12);
  const auto t = transform(view, {1.0, 2.0, -7.0});
  EXPECT_NEAR(t[2], -10.0, 1e-12);  // the target lies on −z of view space
  const Mat4 proj = perspective(std::numbers::pi / 2.0, 2.0, 1.0, 100.0);
  const auto n = transform(proj, {0.0, 0.0, -1.0});
  const auto f = transform(proj, {0.0, 0.0, -100.0});
  EXPECT_NEAR(n[2] / n[3], 0.0, 1e-12);
  EXPECT_NEAR(f[2] / f[3], 1.0, 1e-12);
  const auto corner = transform(proj, {2.0, 1.0, -1.0});  // fov 90°, aspect 2: the top-right edge
  EXPECT_NEAR(corner[0] / corner[3], 1.0, 1e-12);
  EXPECT_NEAR(corner[1] / corner[3], 1.0, 1e-12);
}

TEST(LodFrustum, PlanesSeparateInsideFromOutside) {
  const Camera cam{.position_m = {0.0, 10.0, 0.0},
                   .target_m = {100.0, 10.0, 0.0},
                   .fov_y_rad = std::numbers::pi / 3.0,
                   .aspect = 16.0 / 9.0,
                   .near_m = 1.0,
                   .far_m = 1000.0};
  ASSERT_TRUE(validate(cam).ok());
  const Frustum f = camera_frustum(cam);
  for (const Plane& p : f.planes) {
    EXPECT_NEAR(p.nx * p.nx + p.ny * p.ny + p.nz * p.nz, 1.0, 1e-12);
  }
  EXPECT_TRUE(inside(f, {50.0, 10.0, 0.0}));
  EXPECT_TRUE(inside(f, {50.0, 10.0 - 50.0 * std::tan(0.5), 0.0}));  // just inside 30° down
  EXPECT_FALSE(inside(f, {50.0, 10.0 - 50.0 * std::tan(0.55), 0.0}));
  EXPECT_FALSE(inside(f, {-5.0, 10.0, 0.0}));    // behind
  EXPECT_FALSE(inside(f, {0.5, 10.0, 0.0}));     // before the near plane
  EXPECT_FALSE(inside(f, {1001.0, 10.0, 0.0}));  // beyond the far plane
  EXPECT_FALSE(inside(f, {50.0, 10.0, 60.0}));   // right of 45.7° (16:9 at 60° vertical)
  EXPECT_TRUE(inside(f, {50.0, 10.0, 50.0}));
  // A box straddling a plane is visible; one wholly outside is not.
  EXPECT_TRUE(box_visible(f, {-5.0, 10.0, 0.0}, {6.0, 1.0, 1.0}));
  EXPECT_FALSE(box_visible(f, {-5.0, 10.0, 0.0}, {4.0, 1.0, 1.0}));
}

TEST(LodFrustum, StraightDownIsWellDefined) {
  const Frustum f = camera_frustum({.position_m = {3.0, 50.0, 4.0}, .target_m = {3.0, 0.0, 4.0}});
  for (const Plane& p : f.planes) {
    EXPECT_TRUE(std::isfinite(p.nx) && std::isfinite(p.ny) && std::isfinite(p.nz) &&
                std::isfinite(p.d));
  }
  EXPECT_TRUE(inside(f, {3.0, 0.0, 4.0}));
  EXPECT_TRUE(inside(f, {20.0, 0.0, 20.0}));
  EXPECT_FALSE(inside(f, {3.0, 60.0, 4.0}));
  EXPECT_FALSE(inside(f, {200.0, 0.0, 4.0}));
}

TEST(LodFrustum, CameraValidation) {
  EXPECT_NE(validate(Camera{.position_m = {1, 2, 3}, .target_m = {1, 2, 3}})
                .message()
                .find("camera.target_m"),
            std::string::npos);
  EXPECT_FALSE(
      validate(Camera{.position_m = {0, 1, 0}, .target_m = {1, 0, 0}, .near_m = 0.0}).ok());
  EXPECT_FALSE(
      validate(Camera{.position_m = {0, 1, 0}, .target_m = {1, 0, 0}, .near_m = 5, .far_m = 4})
          .ok());
  EXPECT_FALSE(validate(Camera{.position_m = {NAN, 1, 0}}).ok());
}

}  // namespace
