// Hulls: the built-in shapes are closed and outward, their mass properties are the closed forms
// of the solids (box: V = abc, I_xx = m(b² + c²)/12; a regular n-gon prism: V =
// ½·n·r²·sin(2π/n)·h), and bad meshes, sizes and densities are refused with invalid_argument.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "ocean/bodies.hpp"

namespace {

using namespace ocean::bodies;

TEST(Hull, BoxMassPropertiesAreTheSolidBoxes) {
  const auto box = box_hull({2.0, 0.5, 3.0}, 3);
  ASSERT_TRUE(box.ok()) << box.status().message();
  ASSERT_TRUE(validate(box.value()).ok()) << validate(box.value()).message();
  const MassProperties m = mass_properties(box.value());
  EXPECT_NEAR(m.volume_m3, 3.0, 1e-12);
  for (double c : m.centroid_m) EXPECT_NEAR(c, 0.0, 1e-12);
  const double v = m.volume_m3;  // density 1: mass = volume
  EXPECT_NEAR(m.inertia[0], v * (0.25 + 9.0) / 12.0, 1e-12);
  EXPECT_NEAR(m.inertia[4], v * (4.0 + 9.0) / 12.0, 1e-12);
  EXPECT_NEAR(m.inertia[8], v * (4.0 + 0.25) / 12.0, 1e-12);
  EXPECT_NEAR(m.inertia[1], 0.0, 1e-12);
  EXPECT_NEAR(m.inertia[5], 0.0, 1e-12);
}

TEST(Hull, BuoyIsAClosedPrism) {
  const int n = 16;
  const auto buoy = buoy_hull(0.8, 1.5, n);
  ASSERT_TRUE(buoy.ok()) << buoy.status().message();
  ASSERT_TRUE(validate(buoy.value()).ok()) << validate(buoy.value()).message();
  const MassProperties m = mass_properties(buoy.value());
  EXPECT_NEAR(m.volume_m3, 0.5 * n * 0.64 * std::sin(2.0 * std::numbers::pi / n) * 1.5, 1e-12);
  for (double c : m.centroid_m) EXPECT_NEAR(c, 0.0, 1e-12);
}

TEST(Hull, BoatIsClosedAndCentred) {
  const auto boat = boat_hull(8.0, 3.0, 1.2);
  ASSERT_TRUE(boat.ok()) << boat.status().message();
  ASSERT_TRUE(validate(boat.value()).ok()) << validate(boat.value()).message();
  const MassProperties m = mass_properties(boat.value());
  // Inside the bounding box L·B·D and more than half of the box's half-ellipse prism at the
  // midship section's size tapered to the ends.
  EXPECT_LT(m.volume_m3, 8.0 * 3.0 * 1.2);
  EXPECT_GT(m.volume_m3, 0.25 * 8.0 * 3.0 * 1.2);
  for (double c : m.centroid_m) EXPECT_NEAR(c, 0.0, 1e-9);
  EXPECT_GT(m.inertia[8], m.inertia[0]);  // long: pitch/yaw inertia exceeds roll inertia
}

TEST(Hull, BoatTopsideStandsOnTheDeckInsideTheSheer) {
  // The deck, bulwark, cabin and windows are drawn with the hull in its frame and left out of the
  // buoyancy: each part lies on or above the deck (the hull's highest level), within the hull's
  // length and beam, and the cabin's blocks are closed and wound outwards.
  const Hull hull = boat_hull(8.0, 3.0, 1.2).value();
  double deck = -1e9, x_lo = 1e9, x_hi = -1e9, z_hi = 0.0;
  for (const auto& v : hull.vertices) {
    deck = std::max(deck, v[1]);
    x_lo = std::min(x_lo, v[0]);
    x_hi = std::max(x_hi, v[0]);
    z_hi = std::max(z_hi, std::abs(v[2]));
  }
  const auto top = boat_topside(8.0, 3.0, 1.2);
  ASSERT_TRUE(top.ok()) << top.status().message();
  for (const Hull* part : {&top.value().deck, &top.value().bulwark, &top.value().cabin,
                           &top.value().windows}) {
    ASSERT_FALSE(part->triangles.empty());
    for (const auto& v : part->vertices) {
      EXPECT_GE(v[1], deck - 1e-9);
      EXPECT_GE(v[0], x_lo - 1e-9);
      EXPECT_LE(v[0], x_hi + 1e-9);
      EXPECT_LE(std::abs(v[2]), z_hi + 1e-9);
    }
  }
  EXPECT_TRUE(validate(top.value().cabin).ok()) << validate(top.value().cabin).message();
  // The cabin's roof: 0.9·D above the planking, which is 0.03·D thick.
  double roof = -1e9;
  for (const auto& v : top.value().cabin.vertices) roof = std::max(roof, v[1]);
  EXPECT_NEAR(roof - deck, 0.03 * 1.2 + 0.9 * 1.2, 1e-9);
  EXPECT_FALSE(boat_topside(8.0, -1.0, 1.2).ok());
}

TEST(Hull, RefusesOpenInsideOutAndNonFiniteMeshes) {
  const Hull box = box_hull({1.0, 1.0, 1.0}, 1).value();
  Hull open = box;
  open.triangles.pop_back();
  EXPECT_EQ(validate(open).code(), ocean::ErrorCode::invalid_argument);
  Hull inside_out = box;
  for (auto& t : inside_out.triangles) std::swap(t[1], t[2]);
  EXPECT_EQ(validate(inside_out).code(), ocean::ErrorCode::invalid_argument);
  Hull nan = box;
  nan.vertices[0][1] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(validate(nan).code(), ocean::ErrorCode::invalid_argument);
  Hull out_of_range = box;
  out_of_range.triangles[0][0] = 999;
  EXPECT_EQ(validate(out_of_range).code(), ocean::ErrorCode::invalid_argument);
  EXPECT_EQ(validate(Hull{}).code(), ocean::ErrorCode::invalid_argument);
}

TEST(Hull, RefusesBadSizesAndDensities) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(box_hull({1.0, -1.0, 1.0}).ok());
  EXPECT_FALSE(box_hull({1.0, nan, 1.0}).ok());
  EXPECT_FALSE(box_hull({1.0, 1.0, 1.0}, 0).ok());
  EXPECT_FALSE(buoy_hull(0.5, 1.0, 2).ok());
  EXPECT_FALSE(buoy_hull(nan, 1.0).ok());
  EXPECT_FALSE(boat_hull(8.0, 0.0, 1.0).ok());
  const Hull box = box_hull({1.0, 1.0, 1.0}).value();
  for (double density : {-500.0, 0.0, nan, std::numeric_limits<double>::infinity()}) {
    const auto body = solid_body(box, density);
    ASSERT_FALSE(body.ok()) << density;
    EXPECT_EQ(body.status().code(), ocean::ErrorCode::invalid_argument);
    EXPECT_NE(body.status().message().find("density"), std::string::npos);
  }
  EXPECT_FALSE(solid_body(box, 500.0, {.linear_mps = -1.0}).ok());
}

TEST(Hull, RefusesBadBodyParametersAndStates) {
  BodyParams p = solid_body(box_hull({1.0, 1.0, 1.0}).value(), 500.0).value();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_TRUE(FloatingBody::make(p, {}).ok());
  BodyParams bad_mass = p;
  bad_mass.mass_kg = -1.0;
  EXPECT_EQ(FloatingBody::make(bad_mass, {}).status().code(), ocean::ErrorCode::invalid_argument);
  bad_mass.mass_kg = nan;
  EXPECT_EQ(FloatingBody::make(bad_mass, {}).status().code(), ocean::ErrorCode::invalid_argument);
  BodyParams bad_inertia = p;
  bad_inertia.inertia_kgm2[0] = -1.0;
  EXPECT_FALSE(FloatingBody::make(bad_inertia, {}).ok());
  EXPECT_FALSE(FloatingBody::make(p, {.position_m = {0.0, nan, 0.0}}).ok());
  EXPECT_FALSE(FloatingBody::make(p, {.orientation = {2.0, 0.0, 0.0, 0.0}}).ok());
  EXPECT_FALSE(FloatingBody::make(p, {}, {.density_kgpm3 = -1025.0}).ok());
  auto body = FloatingBody::make(p, {}).value();
  EXPECT_EQ(body.step(calm_surface(), 0.0).code(), ocean::ErrorCode::invalid_argument);
  EXPECT_EQ(body.step(calm_surface(), nan).code(), ocean::ErrorCode::invalid_argument);
}

TEST(Hull, HeadingTurnsXTowardsZ) {
  const Vec3 v = rotate(orientation_from_heading(90.0), {1.0, 0.0, 0.0});
  EXPECT_NEAR(v[0], 0.0, 1e-12);
  EXPECT_NEAR(v[2], 1.0, 1e-12);
}

}  // namespace
