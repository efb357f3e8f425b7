// The objects of `ocean render --object KIND,X,Y,Z,HEADING,SPEED --float` (object_flags.hpp): the
// speed field, and the flags turned into the world's objects (ocean/world.hpp, whose own tests
// drive them) beside the renderer's meshes.
#include <gtest/gtest.h>

#include <vector>

#include "object_flags.hpp"

namespace {

using ocean::cli::load_objects;
using ocean::cli::ObjectSpec;
using ocean::cli::parse_object_spec;

TEST(DrivenObjects, TheSpeedFieldIsParsedAndChecked) {
  auto spec = parse_object_spec("boat,1,0,2,30,5.5");
  ASSERT_TRUE(spec.ok()) << spec.status().message();
  EXPECT_EQ(spec.value().speed_mps, 5.5);
  EXPECT_EQ(spec.value().heading_deg, 30.0);
  EXPECT_EQ(parse_object_spec("boat,1,0,2,30").value().speed_mps, 0.0);
  for (const char* bad : {"boat,0,0,0,0,-1", "boat,0,0,0,0,31", "boat,0,0,0,0,nan"}) {
    auto r = parse_object_spec(bad);
    ASSERT_FALSE(r.ok()) << bad;
    EXPECT_NE(r.status().message().find("--object speed"), std::string::npos)
        << r.status().message();
  }
  EXPECT_FALSE(parse_object_spec("boat,0,0,0,0,1,2").ok());
}

TEST(DrivenObjects, EachObjectIsAWorldObjectWithItsMeshes) {
  const std::vector<ObjectSpec> specs{
      {.kind = "boat", .position_m = {10.0, 0.0, -20.0}, .heading_deg = 90.0, .speed_mps = 5.0},
      {.kind = "buoy", .position_m = {-10.0, 0.0, 0.0}}};
  auto objects = load_objects(specs, true);
  ASSERT_TRUE(objects.ok()) << objects.status().message();
  const ocean::cli::RenderObjects& o = objects.value();
  ASSERT_EQ(o.objects.size(), 2u);
  // The boat: its hull, deck, bulwark, cabin and windows (bodies::boat_topside); the buoy: one.
  ASSERT_EQ(o.meshes.size(), 6u);
  EXPECT_EQ(o.mesh_indices, (std::vector<std::vector<std::uint32_t>>{{0, 1, 2, 3, 4}, {5}}));
  EXPECT_EQ(o.objects[0].name, "--object boat");
  EXPECT_EQ(o.objects[0].speed_mps, 5.0);
  EXPECT_EQ(o.objects[0].heading_deg, 90.0);
  EXPECT_EQ(o.objects[0].density_kgpm3, ocean::world::kBoatDensity_kgpm3);
  EXPECT_EQ(o.objects[1].density_kgpm3, ocean::world::kBuoyDensity_kgpm3);
  // The mesh is the hull, flat-shaded: three corners per triangle.
  EXPECT_EQ(o.meshes[0].positions.size(), 3 * o.objects[0].hull.triangles.size());
  // A speed drives a floating object only: the world refuses it, naming the flag.
  ocean::SimulationConfig c;
  c.resolution = 16;
  c.cascade_patch_sizes_m = {100.0};
  auto world = ocean::world::World::make({.objects = o.objects}, c);
  ASSERT_FALSE(world.ok());
  EXPECT_NE(world.status().message().find("--object boat"), std::string::npos);
}

}  // namespace
