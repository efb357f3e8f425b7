// A located view as the renderer's camera (docs/vr.md V.1), against OpenXR's definitions: a view
// looks along its pose's −Z with +Y up; a rotation θ about +Z rolls the picture's up to
// (−sin θ, cos θ, 0); XrFovf's angles become the camera's asymmetric frustum unchanged; the
// head of a stereo selection is the eyes' mid-point. Pure arithmetic: no runtime, no device.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <numbers>

#include "ocean/xr.hpp"

namespace {

using ocean::lod::Vec3;

ocean::xr::Pose about_axis(Vec3 axis, double angle_rad) {
  const double s = std::sin(0.5 * angle_rad);
  return {.orientation = {axis.x * s, axis.y * s, axis.z * s, std::cos(0.5 * angle_rad)}};
}

Vec3 forward_of(const ocean::lod::Camera& c) {
  return {c.target_m.x - c.position_m.x, c.target_m.y - c.position_m.y,
          c.target_m.z - c.position_m.z};
}

void expect_near(Vec3 a, Vec3 b, const char* what) {
  EXPECT_NEAR(a.x, b.x, 1e-12) << what;
  EXPECT_NEAR(a.y, b.y, 1e-12) << what;
  EXPECT_NEAR(a.z, b.z, 1e-12) << what;
}

TEST(XrEyeCamera, PoseGivesPositionDirectionAndRoll) {
  const Vec3 origin{0.0, 6.0, 0.0};
  ocean::xr::EyeView eye;
  eye.pose.position_m = {0.1, -0.2, 0.3};
  eye.fov = {.left_rad = -0.9, .right_rad = 0.7, .up_rad = 0.6, .down_rad = -0.85};
  ocean::lod::Camera c = ocean::xr::eye_camera(eye, origin, 0.25, 5000.0);
  expect_near(c.position_m, {0.1, 5.8, 0.3}, "position: the pose's plus the origin");
  expect_near(forward_of(c), {0.0, 0.0, -1.0}, "identity: looks along −Z");
  expect_near(c.up, {0.0, 1.0, 0.0}, "identity: +Y up");
  ASSERT_TRUE(c.fov.has_value());
  EXPECT_EQ(c.fov->left_rad, -0.9);
  EXPECT_EQ(c.fov->right_rad, 0.7);
  EXPECT_EQ(c.fov->up_rad, 0.6);
  EXPECT_EQ(c.fov->down_rad, -0.85);
  EXPECT_EQ(c.near_m, 0.25);
  EXPECT_EQ(c.far_m, 5000.0);
  EXPECT_TRUE(ocean::lod::validate(c).ok());

  const double theta = 0.3;  // rolled counter-clockwise as the wearer sees it
  eye.pose.orientation = about_axis({0.0, 0.0, 1.0}, theta).orientation;
  c = ocean::xr::eye_camera(eye, origin, 0.25, 5000.0);
  expect_near(forward_of(c), {0.0, 0.0, -1.0}, "roll keeps the direction");
  expect_near(c.up, {-std::sin(theta), std::cos(theta), 0.0}, "roll turns up");

  eye.pose.orientation = about_axis({0.0, 1.0, 0.0}, std::numbers::pi / 2.0).orientation;
  c = ocean::xr::eye_camera(eye, origin, 0.25, 5000.0);
  expect_near(forward_of(c), {-1.0, 0.0, 0.0}, "a quarter turn left about +Y looks along −X");
  expect_near(c.up, {0.0, 1.0, 0.0}, "yaw keeps up");

  eye.pose.orientation = about_axis({1.0, 0.0, 0.0}, -0.4).orientation;  // looking down
  c = ocean::xr::eye_camera(eye, origin, 0.25, 5000.0);
  expect_near(forward_of(c), {0.0, -std::sin(0.4), -std::cos(0.4)}, "pitch");
  expect_near(c.up, {0.0, std::cos(0.4), -std::sin(0.4)}, "pitch tips up forwards");
}

TEST(XrEyeCamera, HeadIsTheEyesMidPoint) {
  ocean::xr::EyeView left, right;
  left.pose = about_axis({0.0, 0.0, 1.0}, 0.2);
  right.pose = left.pose;
  left.pose.position_m = {-0.032, 0.01, 0.0};
  right.pose.position_m = {0.032, -0.01, 0.002};
  const std::array<ocean::lod::Camera, 2> eyes = {
      ocean::xr::eye_camera(left, {5.0, 6.0, 7.0}, 0.5, 1e5),
      ocean::xr::eye_camera(right, {5.0, 6.0, 7.0}, 0.5, 1e5)};
  const ocean::lod::Camera head = ocean::xr::head_camera(eyes);
  expect_near(head.position_m, {5.0, 6.0, 7.001}, "mid-point");
  expect_near(forward_of(head), forward_of(eyes[0]), "eye 0's direction");
  expect_near(head.up, eyes[0].up, "eye 0's up");
  EXPECT_TRUE(ocean::lod::validate(head).ok());
}

}  // namespace
