// Camera matrices and frustum planes (Vulkan depth range) and the AABB test (eqs. 59–60); the
// rolled camera and the asymmetric frustum of a headset's eye (docs/lod.md L.11–L.13) against the
// definition of OpenXR's XrFovf: a view direction at the side's angle lies on the image's edge.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <numbers>
#include <random>

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

// ---- rolled cameras and asymmetric frusta (L.11–L.13) -----------------------------------------

// A headset's left eye: wider outwards (left) and downwards, as real optics are.
constexpr FovAngles kFrustumEyeFov{
    .left_rad = -0.95, .right_rad = 0.70, .up_rad = 0.60, .down_rad = -0.85};

std::array<double, 3> frustum_ndc(const Mat4& vp, Vec3 p) {
  const auto c = transform(vp, p);
  return {c[0] / c[3], c[1] / c[3], c[2] / c[3]};
}

// A camera at p looking along world −z, rolled by θ counter-clockwise (its up leaning to −x):
// its right is (cos θ, sin θ, 0) and its up (−sin θ, cos θ, 0), so the view direction of
// tangents (a, b) is the world direction a·right + b·up − z.
struct RolledRig {
  Vec3 p{3.0, 7.0, -2.0};
  double theta = 0.0;
  Camera camera(std::optional<FovAngles> fov) const {
    return {.position_m = p,
            .target_m = {p.x, p.y, p.z - 10.0},
            .near_m = 0.25,
            .far_m = 800.0,
            .up = {-std::sin(theta), std::cos(theta), 0.0},
            .fov = fov};
  }
  Vec3 point(double a, double b, double distance) const {
    const double c = std::cos(theta), s = std::sin(theta);
    return {p.x + distance * (a * c - b * s), p.y + distance * (a * s + b * c), p.z - distance};
  }
};

TEST(LodFrustum, AsymmetricEdgesMapToNdcOne) {
  const double tl = std::tan(kFrustumEyeFov.left_rad), tr = std::tan(kFrustumEyeFov.right_rad);
  const double td = std::tan(kFrustumEyeFov.down_rad), tu = std::tan(kFrustumEyeFov.up_rad);
  for (double theta : {0.0, 0.37}) {
    const RolledRig rig{.theta = theta};
    const Camera cam = rig.camera(kFrustumEyeFov);
    ASSERT_TRUE(validate(cam).ok()) << validate(cam).message();
    const Mat4 vp = view_projection(cam);
    for (double d : {0.25, 3.0, 800.0}) {
      // On each side, anywhere along it: NDC ±1 on that axis.
      EXPECT_NEAR(frustum_ndc(vp, rig.point(tl, 0.1, d))[0], -1.0, 1e-12);
      EXPECT_NEAR(frustum_ndc(vp, rig.point(tr, -0.3, d))[0], 1.0, 1e-12);
      EXPECT_NEAR(frustum_ndc(vp, rig.point(0.2, td, d))[1], -1.0, 1e-12);
      EXPECT_NEAR(frustum_ndc(vp, rig.point(-0.4, tu, d))[1], 1.0, 1e-12);
      // The axis (tangents 0, 0) lies off the centre by the asymmetry.
      const auto axis = frustum_ndc(vp, rig.point(0.0, 0.0, d));
      EXPECT_NEAR(axis[0], -(tr + tl) / (tr - tl), 1e-12);
      EXPECT_NEAR(axis[1], -(tu + td) / (tu - td), 1e-12);
    }
    EXPECT_NEAR(frustum_ndc(vp, rig.point(0.1, 0.1, 0.25))[2], 0.0, 1e-12);   // near plane: depth 0
    EXPECT_NEAR(frustum_ndc(vp, rig.point(0.1, 0.1, 800.0))[2], 1.0, 1e-12);  // far plane: depth 1
  }
}

TEST(LodFrustum, RollRotatesThePictureTheOtherWay) {
  // Tangents measured in the picture (NDC scaled back by the side's tangents) turn by −θ when
  // the camera rolls by θ: the world stays put, the picture's axes turn with the head.
  const double tl = std::tan(kFrustumEyeFov.left_rad), tr = std::tan(kFrustumEyeFov.right_rad);
  const double td = std::tan(kFrustumEyeFov.down_rad), tu = std::tan(kFrustumEyeFov.up_rad);
  const auto tangents = [&](const std::array<double, 3>& n) {
    return std::array<double, 2>{0.5 * (n[0] * (tr - tl) + (tr + tl)),
                                 0.5 * (n[1] * (tu - td) + (tu + td))};
  };
  const Vec3 world{3.0 + 0.3 * 20.0, 7.0 + 0.2 * 20.0, -2.0 - 20.0};
  for (std::optional<FovAngles> fov : {std::optional<FovAngles>{}, std::optional(kFrustumEyeFov)}) {
    const RolledRig level{};
    const auto a0 = fov ? tangents(frustum_ndc(view_projection(level.camera(fov)), world))
                        : std::array<double, 2>{};
    for (double theta : {0.1, 0.5, -1.2}) {
      const RolledRig rolled{.theta = theta};
      if (!fov) {
        // Symmetric, aspect 1: NDC itself turns by −θ.
        Camera a = level.camera(fov), b = rolled.camera(fov);
        a.aspect = b.aspect = 1.0;
        const auto n0 = frustum_ndc(view_projection(a), world),
                   n1 = frustum_ndc(view_projection(b), world);
        EXPECT_NEAR(n1[0], std::cos(theta) * n0[0] + std::sin(theta) * n0[1], 1e-12);
        EXPECT_NEAR(n1[1], -std::sin(theta) * n0[0] + std::cos(theta) * n0[1], 1e-12);
        continue;
      }
      const auto a1 = tangents(frustum_ndc(view_projection(rolled.camera(fov)), world));
      EXPECT_NEAR(a1[0], std::cos(theta) * a0[0] + std::sin(theta) * a0[1], 1e-12);
      EXPECT_NEAR(a1[1], -std::sin(theta) * a0[0] + std::cos(theta) * a0[1], 1e-12);
    }
  }
}

double plane_distance(const Plane& p, Vec3 q) { return p.nx * q.x + p.ny * q.y + p.nz * q.z + p.d; }

TEST(LodFrustum, AsymmetricPlanesHoldTheCorners) {
  const RolledRig rig{.theta = 0.37};
  const Camera cam = rig.camera(kFrustumEyeFov);
  const Frustum f = camera_frustum(cam);
  const std::array<Vec3, 8> corners = frustum_corners(cam);
  const double t[4][2] = {{std::tan(kFrustumEyeFov.left_rad), std::tan(kFrustumEyeFov.down_rad)},
                          {std::tan(kFrustumEyeFov.right_rad), std::tan(kFrustumEyeFov.down_rad)},
                          {std::tan(kFrustumEyeFov.right_rad), std::tan(kFrustumEyeFov.up_rad)},
                          {std::tan(kFrustumEyeFov.left_rad), std::tan(kFrustumEyeFov.up_rad)}};
  // The planes each corner lies on: left/right, bottom/top, near/far (the corner order).
  const int on[4][2] = {{0, 2}, {1, 2}, {1, 3}, {0, 3}};
  for (int k = 0; k < 8; ++k) {
    const double d = k < 4 ? cam.near_m : cam.far_m;
    const Vec3 expected = rig.point(t[k % 4][0], t[k % 4][1], d);
    const Vec3 c = corners[static_cast<std::size_t>(k)];
    EXPECT_NEAR(c.x, expected.x, 1e-9 * d);
    EXPECT_NEAR(c.y, expected.y, 1e-9 * d);
    EXPECT_NEAR(c.z, expected.z, 1e-9 * d);
    for (int i = 0; i < 6; ++i) {
      const bool on_plane = i == on[k % 4][0] || i == on[k % 4][1] || i == (k < 4 ? 4 : 5);
      const double dist = plane_distance(f.planes[static_cast<std::size_t>(i)], expected);
      if (on_plane) {
        EXPECT_NEAR(dist, 0.0, 1e-9 * d) << "corner " << k << " plane " << i;
      } else {
        EXPECT_GT(dist, 0.0) << "corner " << k << " plane " << i;
      }
    }
  }
  // Just outside each side (1 % beyond its tangent) is outside; just inside is inside.
  EXPECT_FALSE(inside(f, rig.point(1.01 * t[0][0], 0.0, 50.0)));
  EXPECT_TRUE(inside(f, rig.point(0.99 * t[0][0], 0.0, 50.0)));
  EXPECT_FALSE(inside(f, rig.point(1.01 * t[2][0], 0.0, 50.0)));
  EXPECT_TRUE(inside(f, rig.point(0.99 * t[2][0], 0.0, 50.0)));
  EXPECT_FALSE(inside(f, rig.point(0.0, 1.01 * t[0][1], 50.0)));
  EXPECT_TRUE(inside(f, rig.point(0.0, 0.99 * t[0][1], 50.0)));
  EXPECT_FALSE(inside(f, rig.point(0.0, 1.01 * t[2][1], 50.0)));
  EXPECT_TRUE(inside(f, rig.point(0.0, 0.99 * t[2][1], 50.0)));
}

TEST(LodFrustum, BoundingFrustumHoldsBothEyes) {
  // Two canted, rolled eyes with mirrored asymmetric fields of view, 64 mm apart.
  Camera left = RolledRig{.theta = 0.3}.camera(kFrustumEyeFov);
  Camera right = left;
  right.fov = FovAngles{.left_rad = -kFrustumEyeFov.right_rad,
                        .right_rad = -kFrustumEyeFov.left_rad,
                        .up_rad = kFrustumEyeFov.up_rad,
                        .down_rad = kFrustumEyeFov.down_rad};
  right.position_m.x += 0.064 * std::cos(0.3), right.position_m.y += 0.064 * std::sin(0.3);
  right.target_m = {right.position_m.x + 1.0, right.position_m.y, right.position_m.z - 10.0};
  const Frustum hull = bounding_frustum(left, right);
  for (const Camera& eye : {left, right})
    for (const Vec3& c : frustum_corners(eye))
      for (const Plane& p : hull.planes) EXPECT_GE(plane_distance(p, c), -1e-9 * left.far_m);
  // Points drawn inside either frustum are inside the hull.
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (const Camera& eye : {left, right}) {
    const std::array<Vec3, 8> c = frustum_corners(eye);
    const Frustum own = camera_frustum(eye);
    for (int i = 0; i < 200; ++i) {
      const double a = u(rng), b = u(rng), z = u(rng);
      const auto lerp = [](Vec3 p, Vec3 q, double t) {
        return Vec3{p.x + t * (q.x - p.x), p.y + t * (q.y - p.y), p.z + t * (q.z - p.z)};
      };
      const Vec3 nearp = lerp(lerp(c[0], c[1], a), lerp(c[3], c[2], a), b);
      const Vec3 farp = lerp(lerp(c[4], c[5], a), lerp(c[7], c[6], a), b);
      const Vec3 q = lerp(nearp, farp, z);
      if (!inside(own, q)) continue;  // on a side within rounding
      EXPECT_TRUE(inside(hull, q));
    }
  }
  // Parallel eyes (the desktop's stereo_eyes): the left eye's left plane, the right eye's right
  // plane, unmoved.
  Camera a{.position_m = {0.0, 5.0, 0.0}, .target_m = {0.0, 5.0, -10.0}, .near_m = 0.2};
  Camera b = a;
  b.position_m.x += 0.064, b.target_m.x += 0.064;
  const Frustum pair = bounding_frustum(a, b);
  const Frustum fa = camera_frustum(a), fb = camera_frustum(b);
  EXPECT_EQ(pair.planes[0].d, fa.planes[0].d);
  EXPECT_EQ(pair.planes[0].nx, fa.planes[0].nx);
  EXPECT_EQ(pair.planes[1].d, fb.planes[1].d);
  EXPECT_EQ(pair.planes[1].nx, fb.planes[1].nx);
}

TEST(LodFrustum, DefaultCameraIsTheSymmetricOne) {
  // Cameras that set neither up nor fov keep the symmetric projection and level horizon bit
  // for bit.
  const Camera c{.position_m = {1.5, 20.0, -3.0}, .target_m = {40.0, 0.0, 70.0}};
  const Mat4 expected =
      perspective(c.fov_y_rad, c.aspect, c.near_m, c.far_m) * look_at(c.position_m, c.target_m);
  EXPECT_EQ(view_projection(c).m, expected.m);
  EXPECT_EQ(vertical_fov_rad(c), c.fov_y_rad);
  Camera a = c;
  a.fov = kFrustumEyeFov;
  EXPECT_DOUBLE_EQ(vertical_fov_rad(a), 1.45);
}

TEST(LodFrustum, AsymmetricCameraValidation) {
  Camera c = RolledRig{}.camera(kFrustumEyeFov);
  ASSERT_TRUE(validate(c).ok());
  Camera bad = c;
  bad.fov->left_rad = 0.8;  // right of the right side
  EXPECT_NE(validate(bad).message().find("camera.fov.right_rad"), std::string::npos);
  bad = c, bad.fov->up_rad = -0.9;
  EXPECT_NE(validate(bad).message().find("camera.fov.up_rad"), std::string::npos);
  bad = c, bad.fov->down_rad = -1.6;  // beyond a right angle
  EXPECT_NE(validate(bad).message().find("camera.fov.down_rad"), std::string::npos);
  bad = c, bad.fov->right_rad = NAN;
  EXPECT_FALSE(validate(bad).ok());
  bad = c, bad.up = {0.0, 0.0, 0.0};
  EXPECT_NE(validate(bad).message().find("camera.up"), std::string::npos);
  bad = c, bad.fov.reset(), bad.aspect = 0.0;  // the symmetric form's fields count again
  EXPECT_FALSE(validate(bad).ok());
  bad = c, bad.aspect = 0.0;  // ignored with fov
  EXPECT_TRUE(validate(bad).ok());
}

}  // namespace
