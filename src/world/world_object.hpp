// src/world/world_object.hpp — one object of a World, as world.cpp steps it and layer.cpp reads
// its track. Private to the module.
#pragma once

#include <memory>
#include <optional>

#include "ocean/world.hpp"

namespace ocean::world {

struct World::Object {
  Pose start;                        // where it was placed (and stays, when nothing floats)
  double heading_deg = 0.0;          // the straight course of a driven object
  double speed_mps = 0.0;            // commanded; > 0: driven
  std::optional<Circle> circle;      // driven round it instead
  std::array<double, 3> centre_m{};  // the object frame's point that is the body's centre
  std::array<double, 2> size_m{};    // the hull's length along x and breadth across z
  std::array<double, 3> box_centre_m{};  // the centre of the hull's x–z extent, object frame
  std::unique_ptr<bodies::FloatingBody> body;    // floating
  std::optional<bodies::Propulsion> propulsion;  // driven
  std::optional<waves::WakeTrack> track;         // driven
  bodies::BodyState settled;  // circling: at rest in calm water, heading 0
};

}  // namespace ocean::world
